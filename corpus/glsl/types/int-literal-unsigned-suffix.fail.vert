// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "There are no letter suffixes."
#version 110
void main()
{
    int i = 1u;
    gl_Position = vec4(float(i));
}
