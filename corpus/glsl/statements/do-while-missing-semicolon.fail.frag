// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "DO statement WHILE LEFT_PAREN expression RIGHT_PAREN SEMICOLON"
void main()
{
    int n = 0;
    do {
        n++;
    } while (n < 3)
    gl_FragColor = vec4(float(n));
}
