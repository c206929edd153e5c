// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "bit-wise and (reserved) &" and "Those marked reserved are illegal."
#version 110
uniform int a;
void main()
{
    int c = a & 3;
    gl_Position = vec4(float(c));
}
