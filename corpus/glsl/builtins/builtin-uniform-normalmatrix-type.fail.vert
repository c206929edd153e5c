// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.5: "uniform mat3 gl_NormalMatrix;"
void main()
{
    mat4 m = gl_NormalMatrix;
    gl_Position = m * gl_Vertex;
}
