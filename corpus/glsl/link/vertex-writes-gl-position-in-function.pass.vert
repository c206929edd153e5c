// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.1: gl_Position "can be written at any time during shader execution."
#version 110
void place()
{
    gl_Position = ftransform();
}
void main()
{
    place();
}
