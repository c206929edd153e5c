// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "hexadecimal-constant : 0x hexadecimal-digit / 0X hexadecimal-digit / hexadecimal-constant hexadecimal-digit" (0x10 is sixteen)
// 4.1.9 "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
void main()
{
    float a[0x10];
    a[16] = 1.0;
    gl_FragColor = vec4(a[0]);
}
