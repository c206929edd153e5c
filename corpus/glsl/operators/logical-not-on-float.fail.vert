// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The logical unary operator not (!). It operates only on a Boolean expression"
#version 110
uniform float a;
void main()
{
    bool c = !a;
    gl_Position = vec4(float(c));
}
