// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1.1: "a function may not call itself either directly or indirectly." (the recursive call is reachable from main)
#version 110
float g(float x);
float f(float x)
{
    return g(x);
}
float g(float x)
{
    return x > 1.0 ? f(x * 0.5) : x;
}
void main()
{
    gl_FragColor = vec4(f(4.0));
}
