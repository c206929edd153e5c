// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.8: "Fragment processing functions are only available in shaders intended for use on the fragment processor."
void main()
{
    gl_Position = gl_Vertex * fwidth(gl_Vertex.x);
}
