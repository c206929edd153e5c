// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1.1: "Recursion means having any function appearing more than once at any one time in the run-time stack of function calls. That is, a function may not call itself either directly or indirectly."
#version 110
float fact(float n)
{
    if (n <= 1.0)
        return 1.0;
    return n * fact(n - 1.0);
}
void main()
{
    gl_Position = vec4(fact(3.0));
}
