// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "The name shares the same name space as other variables and types, with the same scoping rules."
#version 110
struct S {
    float x;
};
float S;
void main()
{
    gl_Position = vec4(0.0);
}
