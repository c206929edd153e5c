// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.7: "The equality and assignment operators are only valid if the two operands' types are of the same declared structure."
struct A {
    float x;
};
struct B {
    float x;
};
uniform A a;
uniform B b;
void main()
{
    bool e = a == b;
    gl_FragColor = vec4(float(e));
}
