// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "All variables and functions must be declared before being used."
#version 110
void main()
{
    gl_Position = vec4(twice(1.0));
}
float twice(float x)
{
    return 2.0 * x;
}
