// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "The function main is used as the entry point to a shader."
#version 110
float helper(float x)
{
    return x * 2.0;
}
void main()
{
    gl_Position = vec4(helper(0.5));
}
