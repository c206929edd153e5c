// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "conditional_expression: logical_or_expression QUESTION expression COLON conditional_expression" (the second operand is a full expression)
#version 110
uniform bool p;
void main()
{
    float x = 0.0;
    float y = p ? x = 1.0 : 2.0;
    gl_Position = vec4(x, y, 0.0, 1.0);
}
