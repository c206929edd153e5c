// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The sequence ( , ) operator ... All expressions are evaluated, in order, from left to right."; 9: "for_rest_statement: conditionopt SEMICOLON expression"
void main()
{
    int i;
    int j;
    float s = 0.0;
    for (i = 0, j = 4; i < j; i++, j--)
        s += 1.0;
    gl_Position = vec4(s);
}
