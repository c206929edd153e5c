// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.6 "the OpenGL Shading Language defines support for 2x2, 3x3, and 4x4 matrices of floating point numbers."
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
#version 110
void main()
{
    mat2 m = vec4(1.0);
    gl_Position = vec4(m[0], m[1]);
}
