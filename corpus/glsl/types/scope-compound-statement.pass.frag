// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "Otherwise, if it is declared as a statement within a compound statement, it is scoped to the end of that compound statement."
void main()
{
    float y = 0.0;
    {
        float x = 1.0;
        y = x;
    }
    float x = 2.0;
    gl_FragColor = vec4(x + y);
}
