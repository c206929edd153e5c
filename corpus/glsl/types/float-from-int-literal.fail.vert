// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
#version 110
void main()
{
    float x = 1;
    gl_Position = vec4(x);
}
