// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.3.6: "The varying qualifier can be used only with float, floating-point vectors, matrices, or arrays of these."
#version 120
varying mat2x4 m;
void main()
{
    m = mat2x4(1.0);
    gl_Position = ftransform();
}
