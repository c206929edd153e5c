// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "In a function, writing to an input-only parameter is allowed ... This can be prevented by declaring a parameter with the const qualifier."
float f(const float x)
{
    x = x * 2.0;
    return x;
}
void main()
{
    gl_FragColor = vec4(f(1.0));
}
