// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 chapter 9: "conditional_expression: logical_or_expression QUESTION expression COLON assignment_expression" (1.10 has conditional_expression there)
#version 120
uniform bool p;
void main()
{
    float x = 0.0;
    p ? x = 1.0 : x = 2.0;
    gl_Position = vec4(x);
}
