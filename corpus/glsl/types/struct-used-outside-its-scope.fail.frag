// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "The name shares the same name space as other variables and types, with the same scoping rules."
// 4.2 "Otherwise, if it is declared as a statement within a compound statement, it is scoped to the end of that compound statement."
void f()
{
    struct Local {
        vec4 color;
    };
}
void main()
{
    Local l;
    gl_FragColor = vec4(0.0);
}
