// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared as a parameter in a function definition, it is scoped until the end of that function definition. A function body has a scope nested inside the function's definition." (parameters share one scope)
#version 110
float f(float x, float x)
{
    return x;
}
void main()
{
    gl_Position = vec4(f(1.0, 2.0));
}
