// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "octal-constant : 0 / octal-constant octal-digit ... octal-digit : one of 01234567"
void main()
{
    int i = 0129;
    gl_FragColor = vec4(float(i));
}
