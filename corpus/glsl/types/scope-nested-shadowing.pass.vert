// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
float x = 1.0;
void main()
{
    vec2 x = vec2(2.0);
    {
        int x = 3;
        x = x + 1;
    }
    gl_Position = vec4(x, 0.0, 1.0);
}
