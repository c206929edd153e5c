// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
uniform float x;
uniform float x;
void main()
{
    gl_Position = vec4(0.0);
}
