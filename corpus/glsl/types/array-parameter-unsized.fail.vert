// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "Arrays declared as formal parameters in a function declaration must specify a size."
#version 110
float first(float a[])
{
    return a[0];
}
void main()
{
    gl_Position = vec4(0.0);
}
