// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "User-defined functions can have multiple declarations, but only one definition." (a prototype that is never called needs no definition)
#version 110
float helper(float x);
void main()
{
    gl_Position = ftransform();
}
