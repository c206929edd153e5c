// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "FOR LEFT_PAREN for_init_statement for_rest_statement RIGHT_PAREN statement_no_new_scope" (the body compound statement does not open a new scope, so redeclaring i is a redeclaration in the same scope, 4.2)
void main()
{
    float s = 0.0;
    for (int i = 0; i < 2; i++) {
        int i = 5;
        s += float(i);
    }
    gl_Position = vec4(s);
}
