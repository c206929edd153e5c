// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared as a parameter in a function definition, it is scoped until the end of that function definition. A function body has a scope nested inside the function's definition."
#version 110
float f(float x)
{
    float x = 2.0;
    return x;
}
void main()
{
    gl_Position = vec4(f(1.0));
}
