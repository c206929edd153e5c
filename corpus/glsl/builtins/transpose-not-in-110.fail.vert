// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.5 lists only matrixCompMult; transpose (GLSL 1.20) is not a 1.10 built-in
#version 110
uniform mat4 m;
void main()
{
    gl_Position = transpose(m) * gl_Vertex;
}
