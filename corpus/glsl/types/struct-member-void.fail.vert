// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member types must be either already defined (there are no forward references), or defined in-place by embedding another struct definition."
// 4.1 "void for functions that do not return a value"
#version 110
struct S {
    void v;
};
void main()
{
    gl_Position = vec4(0.0);
}
