// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these."
#version 110
float f(const float p)
{
    const float q = p;
    return q;
}
void main()
{
    gl_Position = vec4(f(1.0));
}
