// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.8: "Fragment processing functions are only available in shaders intended for use on the fragment processor."
#version 110
void main()
{
    gl_Position = dFdx(gl_Vertex);
}
