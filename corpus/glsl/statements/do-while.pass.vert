// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.3: "do statement while (condition-expression)"; 9: "DO statement WHILE LEFT_PAREN expression RIGHT_PAREN SEMICOLON"
#version 110
void main()
{
    int n = 0;
    do {
        n++;
    } while (n < 3);
    do n--; while (n > 0);
    gl_Position = vec4(float(n));
}
