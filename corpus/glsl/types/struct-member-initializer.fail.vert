// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarations cannot contain initializers."
#version 110
struct S {
    float x = 1.0;
};
void main()
{
    gl_Position = vec4(0.0);
}
