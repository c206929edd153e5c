// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls."
#version 110
float f(const int n)
{
    float a[n];
    a[0] = 1.0;
    return a[0];
}
void main()
{
    gl_Position = vec4(f(2));
}
