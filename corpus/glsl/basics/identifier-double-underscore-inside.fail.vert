// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "In addition, all identifiers containing two consecutive underscores (__) are reserved as possible future keywords."
#version 110
void main()
{
    float a__b = 1.0;
    gl_Position = vec4(a__b);
}
