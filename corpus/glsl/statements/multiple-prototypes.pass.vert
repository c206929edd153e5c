// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "User-defined functions can have multiple declarations, but only one definition."
#version 110
float g(float x);
float g(float x);
float g(float x)
{
    return x + 1.0;
}
float g(float x);
void main()
{
    gl_Position = vec4(g(0.0));
}
