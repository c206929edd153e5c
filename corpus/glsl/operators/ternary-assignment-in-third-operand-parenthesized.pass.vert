// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "primary_expression: ... LEFT_PAREN expression RIGHT_PAREN" (in parentheses the third operand may be an assignment: "conditional_expression: logical_or_expression QUESTION expression COLON conditional_expression")
uniform bool p;
void main()
{
    float x = 0.0;
    p ? x = 1.0 : (x = 2.0);
    gl_Position = vec4(x);
}
