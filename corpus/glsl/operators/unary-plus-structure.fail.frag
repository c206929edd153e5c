// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 5.7: only field selection, equality and assignment operate on structures as whole
// entities; 5.9: unary operators take integer or floating-point values.
struct S { float x; };
uniform S s;
void main()
{
    S t = +s;
    gl_FragColor = vec4(t.x);
}
