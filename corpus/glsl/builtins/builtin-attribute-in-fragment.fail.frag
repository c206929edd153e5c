// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.3: "The following attribute names are built into the OpenGL vertex language and can be used from within a vertex shader"; 4.3.4: attributes belong to vertex shaders
#version 110
void main()
{
    gl_FragColor = gl_Vertex;
}
