// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.4 lists the built-in constants of 1.10; gl_MaxVertexUniformVectors (OpenGL ES) is not among them
#version 110
void main()
{
    gl_Position = vec4(float(gl_MaxVertexUniformVectors));
}
