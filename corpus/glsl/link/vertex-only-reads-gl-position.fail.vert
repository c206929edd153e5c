// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.1: "All executions of a well-formed vertex shader must write a value into this variable." (reading is not writing)
#version 110
varying vec4 pos;
void main()
{
    pos = gl_Position;
}
