// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "No white space is allowed between the digits of an integer constant, including after the leading 0 or after the leading 0x or 0X of a constant."
#version 110
void main()
{
    int i = 0x 1F;
    gl_Position = vec4(float(i));
}
