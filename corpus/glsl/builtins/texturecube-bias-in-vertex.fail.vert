// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "The bias parameter is not accepted in a vertex shader."
#version 110
uniform samplerCube s;
void main()
{
    gl_Position = textureCube(s, gl_Normal, 0.5);
}
