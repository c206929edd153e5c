// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.4 "A decimal point ( . ) is not needed if the exponent part is present."
// 4 "The OpenGL Shading Language is type safe. There are no implicit conversions between types."
#version 110
void main()
{
    int i = 1e3;
    gl_Position = vec4(float(i));
}
