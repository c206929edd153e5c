// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "selection_rest_statement: statement ELSE statement | statement" and "simple_statement: declaration_statement | ..." (a declaration is a statement)
#version 110
uniform bool p;
void main()
{
    if (p)
        float unused = 1.0;
    gl_FragColor = vec4(1.0);
}
