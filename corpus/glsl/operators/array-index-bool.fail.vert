// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.2: "Arrays elements are accessed using an expression whose type is an integer."
#version 110
uniform vec4 w[2];
void main()
{
    gl_Position = w[true];
}
