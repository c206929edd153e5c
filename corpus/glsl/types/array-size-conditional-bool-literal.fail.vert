// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls."
// Reading 4.3.3 literally, operand by operand: ?: is an operator (5.1 lists it; 4.3.3 excludes only function calls), so it is allowed when its operands are integral constant expressions; its first operand here is the literal bool true, not a literal integer value, so the size is not an integral constant expression (compare array-size-conditional-relational.pass.vert).
#version 110
float a[true ? 2 : 3];
void main()
{
    gl_Position = vec4(0.0);
}
