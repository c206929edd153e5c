// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.3 "Literal integer constants can be expressed in decimal (base 10), octal (base 8), or hexadecimal (base 16)"
// 4.1.3 "int i, j = 42;"
#version 110
void main()
{
    int i, j = 42;
    int zero = 0;
    int oct = 017;
    int hex1 = 0x1F;
    int hex2 = 0XaB;
    int hex3 = 0xabcdef;
    int hex4 = 0xABCDEF;
    i = j + zero + oct + hex1 + hex2 + hex3 + hex4;
    gl_Position = vec4(float(i));
}
