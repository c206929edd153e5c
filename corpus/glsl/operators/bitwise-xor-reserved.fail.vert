// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "bit-wise exclusive or (reserved) ^" and "Those marked reserved are illegal."
#version 110
uniform int a;
void main()
{
    int c = a ^ 5;
    gl_Position = vec4(float(c));
}
