// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "The name shares the same name space as other variables and types, with the same scoping rules."
// 4.2 "Otherwise, within one compilation unit, a variable with the same name cannot be re-declared in the same scope. However, a nested scope can override an outer scope's declaration of a particular variable name."
#version 110
struct S {
    float a;
};
void main()
{
    struct S {
        vec4 b;
    };
    S s;
    s.b = vec4(1.0);
    gl_Position = s.b;
}
