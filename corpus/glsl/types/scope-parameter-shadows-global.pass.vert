// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared as a parameter in a function definition, it is scoped until the end of that function definition. A function body has a scope nested inside the function's definition."
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
float x = 1.0;
float twice(float x)
{
    return 2.0 * x;
}
void main()
{
    gl_Position = vec4(twice(x));
}
