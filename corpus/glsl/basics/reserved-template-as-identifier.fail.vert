// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "The following are the keywords reserved for future use. Using them will result in an error"
#version 110
void main()
{
    float template = 1.0;
    gl_Position = vec4(0.0);
}
