// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "For post- and pre-increment and decrement, the expression must be one that could be assigned to (an l-value)."
void main()
{
    float a = 1.0;
    float b = 2.0;
    float c = (a + b)++;
    gl_FragColor = vec4(c);
}
