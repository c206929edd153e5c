// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
void main()
{
    float x = 1.0;
    float x = 2.0;
    gl_Position = vec4(x);
}
