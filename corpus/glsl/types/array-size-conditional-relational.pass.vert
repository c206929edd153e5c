// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls."
// Reading 4.3.3 literally, operand by operand: the operands of ?: are 1 > 0, 2 and 3, and 1 > 0 is an expression whose operands 1 and 0 are literal integer values; every leaf operand is integral, no function is called, so the size is an integral constant expression (compare array-size-conditional-bool-literal.fail.vert).
#version 110
const int n = 2;
float a[n > 1 ? 2 : 3];
void main()
{
    gl_Position = vec4(0.0);
}
