// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared in a while test or a for statement, then it is scoped to the end of the following sub-statement."
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
void main()
{
    float i = 1.0;
    for (int i = 0; i < 2; ++i) {
    }
    gl_Position = vec4(i);
}
