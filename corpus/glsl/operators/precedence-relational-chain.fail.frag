// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: relational operators associate "Left to Right"; 5.9: relational operators "operate only on scalar integer and scalar floating-point expressions", so (a < b) < c compares a bool
uniform float a;
uniform float b;
uniform float c;
void main()
{
    bool r = a < b < c;
    gl_FragColor = vec4(float(r));
}
