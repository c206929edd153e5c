// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.3 "octal-constant : 0 / octal-constant octal-digit ... octal-digit : one of 01234567" (010 is eight)
#version 110
void main()
{
    float a[010];
    a[7] = 1.0;
    gl_Position = vec4(a[7]);
}
