// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "The assignments modulus into (%=), left shift by (<<=), right shift by (>>=), inclusive or into ( |=), and exclusive or into ( ^=). These operators are reserved for future use."
#version 110
uniform int a;
void main()
{
    int c = 7;
    c %= a;
    gl_Position = vec4(float(c));
}
