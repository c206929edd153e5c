// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "However, the const qualifier cannot be used with out or inout."
void f(const out float e)
{
    e = 1.0;
}
void main()
{
    float e;
    f(e);
    gl_Position = vec4(e);
}
