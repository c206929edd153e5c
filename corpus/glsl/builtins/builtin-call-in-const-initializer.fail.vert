// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.3.2: "Initializers for const declarations must be formed from literal values, other const variables ..., or expressions of these. Constructors may be used in such expressions, but function calls may not." (built-in functions included, section 8)
const float s = sin(0.5);
void main()
{
    gl_Position = vec4(s);
}
