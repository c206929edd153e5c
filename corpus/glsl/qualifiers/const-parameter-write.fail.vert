// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "const: a compile-time constant, or a function parameter that is read-only"
#version 110
float twice(const float x)
{
    x = x * 2.0;
    return x;
}
void main()
{
    gl_Position = vec4(twice(1.0));
}
