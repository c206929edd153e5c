// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.3.6: "The varying qualifier can be used only with float, floating-point vectors, matrices, or arrays of these."
#version 120
varying int i;
void main()
{
    i = 1;
    gl_Position = ftransform();
}
