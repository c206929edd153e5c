// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.3: "for (init-expression; condition-expression; loop-expression) sub-statement"; 9: "for_init_statement: expression_statement | declaration_statement", "conditionopt: condition | /* empty */"
void main()
{
    float s = 0.0;
    int i;
    for (i = 0; i < 4; i++)
        s += 1.0;
    for (int j = 0, k = 2; j < k; ++j) {
        s += float(j);
    }
    for (;;) {
        break;
    }
    for (int n = 0; n < 2;)
        n++;
    gl_Position = vec4(s, float(i), 0.0, 1.0);
}
