// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.3 "hexadecimal-constant : 0x hexadecimal-digit / 0X hexadecimal-digit / hexadecimal-constant hexadecimal-digit" (0x10 is sixteen)
void main()
{
    float a[0x10];
    a[0xF] = 1.0;
    gl_FragColor = vec4(a[15]);
}
