// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "User-defined functions can have multiple declarations, but only one definition." A called function that is only declared has no definition to link to.
#version 110
float helper(float x);
void main()
{
    gl_Position = vec4(helper(1.0));
}
