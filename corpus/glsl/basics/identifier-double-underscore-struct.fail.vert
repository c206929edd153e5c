// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "In addition, all identifiers containing two consecutive underscores (__) are reserved as possible future keywords."
#version 110
struct my__type { float x; };
void main()
{
    gl_Position = vec4(0.0);
}
