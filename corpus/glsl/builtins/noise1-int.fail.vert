// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.9: "float noise1 (genType x)" (genType is a float type)
#version 110
uniform int seed;
void main()
{
    gl_Position = vec4(noise1(seed));
}
