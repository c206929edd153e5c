// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "Only one-dimensional arrays may be declared."
#version 110
void main()
{
    float a[2][3];
    gl_Position = vec4(0.0);
}
