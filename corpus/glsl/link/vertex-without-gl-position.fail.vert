// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.1: "All executions of a well-formed vertex shader must write a value into this variable." (gl_Position is never written)
varying vec4 color;
void main()
{
    color = gl_Color;
}
