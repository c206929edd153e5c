// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.4: "vec4 ftransform()" (no parameters)
#version 110
void main()
{
    gl_Position = ftransform(gl_Vertex);
}
