// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "expression_statement: SEMICOLON | expression SEMICOLON"; "compound_statement: LEFT_BRACE RIGHT_BRACE"
void main()
{
    ;
    {}
    { ; }
    gl_FragColor = vec4(1.0);;
}
