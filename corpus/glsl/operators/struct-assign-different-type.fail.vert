// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.7: "The equality and assignment operators are only valid if the two operands' types are of the same declared structure."
#version 110
struct A {
    float x;
};
struct B {
    float x;
};
uniform A a;
void main()
{
    B b = a;
    gl_Position = vec4(b.x);
}
