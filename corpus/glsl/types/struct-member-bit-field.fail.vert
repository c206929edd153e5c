// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators do not contain any qualifiers. Nor do they contain any bit fields."
#version 110
struct S {
    int flags : 3;
};
void main()
{
    gl_Position = vec4(0.0);
}
