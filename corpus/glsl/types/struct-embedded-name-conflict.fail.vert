// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "A name given to an embedded struct is scoped at the same level as the struct it is embedded in."
// 4.1.8 "The name shares the same name space as other variables and types, with the same scoping rules."
#version 110
struct Outer {
    struct Inner {
        float x;
    } inner;
};
struct Inner {
    float y;
};
void main()
{
    gl_Position = vec4(0.0);
}
