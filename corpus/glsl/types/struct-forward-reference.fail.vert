// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member types must be either already defined (there are no forward references), or defined in-place by embedding another struct definition."
#version 110
struct A {
    B b;
};
struct B {
    float x;
};
void main()
{
    gl_Position = vec4(0.0);
}
