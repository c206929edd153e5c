// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "However, the const qualifier cannot be used with out or inout."
#version 110
void f(const inout float e)
{
}
void main()
{
    float e = 1.0;
    f(e);
    gl_FragColor = vec4(e);
}
