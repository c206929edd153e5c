// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these."
attribute vec4 position;
void main()
{
    const vec4 p = position;
    gl_Position = p;
}
