// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "WHILE LEFT_PAREN condition RIGHT_PAREN statement_no_new_scope" (the body does not open a new scope); 4.2: "a variable with the same name cannot be re-declared in the same scope."
#version 110
void main()
{
    int n = 3;
    while (bool more = n > 0) {
        bool more = false;
        n--;
    }
    gl_FragColor = vec4(float(n));
}
