// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "octal-constant : 0 / octal-constant octal-digit ... octal-digit : one of 01234567"
#version 110
void main()
{
    int i = 08;
    gl_Position = vec4(float(i));
}
