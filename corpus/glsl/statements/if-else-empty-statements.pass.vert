// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "selection_rest_statement: statement ELSE statement"; "expression_statement: SEMICOLON"
uniform bool p;
void main()
{
    if (p) ; else ;
    gl_Position = vec4(1.0);
}
