// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.6 "Varying variables are required to have global scope, and must be declared outside of function bodies, before their first use."
#version 110
void setColor()
{
    color = vec4(1.0);
}
varying vec4 color;
void main()
{
    setColor();
    gl_Position = vec4(0.0);
}
