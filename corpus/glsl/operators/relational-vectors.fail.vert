// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: relational operators "operate only on scalar integer and scalar floating-point expressions ... To do component-wise comparisons on vectors, use the built-in functions lessThan ..."
#version 110
uniform vec2 a;
uniform vec2 b;
void main()
{
    bool c = a < b;
    gl_Position = vec4(float(c));
}
