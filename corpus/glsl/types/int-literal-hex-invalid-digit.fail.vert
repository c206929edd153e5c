// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "hexadecimal-constant : 0x hexadecimal-digit / 0X hexadecimal-digit / hexadecimal-constant hexadecimal-digit"
void main()
{
    int i = 0x1G;
    gl_Position = vec4(float(i));
}
