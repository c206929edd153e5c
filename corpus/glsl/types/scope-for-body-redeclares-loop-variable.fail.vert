// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared in a while test or a for statement, then it is scoped to the end of the following sub-statement."
// 9 "FOR LEFT_PAREN for_init_statement for_rest_statement RIGHT_PAREN statement_no_new_scope"
#version 110
void main()
{
    float sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        int i = 2;
        sum += float(i);
    }
    gl_Position = vec4(sum);
}
