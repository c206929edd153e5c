// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.3: "while (condition-expression) sub-statement"; "Both the condition-expression and the init-expression can declare and initialize a variable"
uniform float limit;
void main()
{
    float x = 0.0;
    while (x < limit)
        x += 0.25;
    int n = 3;
    while (bool more = n > 0) {
        n--;
    }
    gl_FragColor = vec4(x, float(n), 0.0, 1.0);
}
