// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "multiplicative (modulus reserved) * / %" and "Those marked reserved are illegal."
#version 110
uniform int a;
uniform int b;
void main()
{
    int c = a % b;
    gl_Position = vec4(float(c));
}
