// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.6 "the OpenGL Shading Language defines support for 2x2, 3x3, and 4x4 matrices of floating point numbers."
// 3.6 mat2x3 is not a keyword of 1.10
#version 110
void main()
{
    mat2x3 m;
    gl_Position = vec4(0.0);
}
