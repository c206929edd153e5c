// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 5.9: the arithmetic unary operators "operate on integer or floating-point values
// (including vectors and matrices)"; f() has no value.
void f(void) {}
void main()
{
    +f();
    gl_Position = vec4(0.0);
}
