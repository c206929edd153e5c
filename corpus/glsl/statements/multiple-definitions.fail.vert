// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "User-defined functions can have multiple declarations, but only one definition."
float g(float x)
{
    return x + 1.0;
}
float g(float x)
{
    return x + 2.0;
}
void main()
{
    gl_Position = vec4(g(0.0));
}
