// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: iteration bodies are "statement" / "statement_no_new_scope", which include "simple_statement: declaration_statement"
uniform bool p;
void main()
{
    int n = 0;
    while (n < 2)
        n++;
    do
        float unused = 1.0;
    while (false);
    for (int i = 0; i < 1; i++)
        float other = 2.0;
    gl_Position = vec4(float(n));
}
