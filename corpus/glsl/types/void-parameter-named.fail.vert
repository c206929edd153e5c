// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1 "void for functions that do not return a value"
#version 110
float f(void x)
{
    return 1.0;
}
void main()
{
    gl_Position = vec4(0.0);
}
