// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "It is an error to construct matrices from other matrices. This is reserved for future use."
#version 110
uniform mat4 m;
void main()
{
    mat3 n = mat3(m);
    gl_Position = vec4(n[0], 1.0);
}
