// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member types must be either already defined (there are no forward references), or defined in-place by embedding another struct definition."
#version 110
struct A {
    float x;
};
struct B {
    A a;
    A list[2];
};
void main()
{
    B b;
    b.a.x = 1.0;
    b.list[1] = b.a;
    gl_Position = vec4(b.list[1].x);
}
