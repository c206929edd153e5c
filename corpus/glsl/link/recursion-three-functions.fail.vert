// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1.1: "a function may not call itself either directly or indirectly."
float a(float x);
float c(float x)
{
    return x > 0.0 ? a(x - 1.0) : 0.0;
}
float b(float x)
{
    return c(x);
}
float a(float x)
{
    return b(x);
}
void main()
{
    gl_Position = vec4(a(3.0));
}
