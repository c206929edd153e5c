// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.6: "selects a single column, whose type is a vector of the same size as the matrix."
#version 110
void main()
{
    mat4 m = mat4(1.0);
    m[1] = vec3(2.0);
    gl_Position = m[1];
}
