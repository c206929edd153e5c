// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "The ternary operator (?:) is also not allowed as an l-value."
uniform bool p;
void main()
{
    float a = 1.0;
    float b = 2.0;
    (p ? a : b) = 3.0;
    gl_Position = vec4(a, b, 0.0, 1.0);
}
