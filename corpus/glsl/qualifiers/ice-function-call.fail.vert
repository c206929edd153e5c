// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls."
#version 110
int two()
{
    return 2;
}
void main()
{
    float a[two()];
    gl_Position = vec4(0.0);
}
