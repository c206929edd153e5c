// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.3: "Variables declared in init-expression or condition-expression are only in scope until the end of the sub-statement of the for loop."
void main()
{
    float s = 0.0;
    for (int i = 0; i < 4; i++)
        s += 1.0;
    gl_FragColor = vec4(s, float(i), 0.0, 1.0);
}
