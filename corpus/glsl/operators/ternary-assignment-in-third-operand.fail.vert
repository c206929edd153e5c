// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "conditional_expression: logical_or_expression QUESTION expression COLON conditional_expression" (the third operand cannot be an assignment, so this parses as (p ? x = 1.0 : x) = 2.0); 5.8: "The ternary operator (?:) is also not allowed as an l-value."
uniform bool p;
void main()
{
    float x = 0.0;
    p ? x = 1.0 : x = 2.0;
    gl_Position = vec4(x);
}
