// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.3.4 (for the 7.3 attributes): "Attribute variables are read-only as far as the vertex shader is concerned."
#version 110
void main()
{
    gl_Vertex = vec4(0.0);
    gl_Position = gl_Vertex;
}
