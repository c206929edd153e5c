// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is legal to declare an array without a size and then later re-declare the same name as an array of the same type and specify a size."
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
float values[3];
float values[4];
void main()
{
    gl_Position = vec4(0.0);
}
