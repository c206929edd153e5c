// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.4 "Attribute variables are required to have global scope, and must be declared outside of function bodies, before their first use."
#version 110
vec4 get()
{
    return position;
}
attribute vec4 position;
void main()
{
    gl_Position = get();
}
