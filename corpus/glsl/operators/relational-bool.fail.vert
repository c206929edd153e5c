// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: relational operators "operate only on scalar integer and scalar floating-point expressions."
#version 110
uniform bool p;
void main()
{
    bool c = p > false;
    gl_Position = vec4(float(c));
}
