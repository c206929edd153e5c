// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: "There is no typecast operator, constructors are used instead."; grammar note "No traditional style type casts."
#version 110
uniform int a;
void main()
{
    float f = (float) a;
    gl_Position = vec4(f);
}
