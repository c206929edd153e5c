// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "Otherwise, if it is declared as a statement within a compound statement, it is scoped to the end of that compound statement."
void main()
{
    {
        float x = 1.0;
    }
    gl_FragColor = vec4(x);
}
