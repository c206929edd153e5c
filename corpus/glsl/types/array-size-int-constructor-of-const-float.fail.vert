// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (the operand f of the constructor is a const float, not a scalar integer variable)
#version 110
const float f = 2.0;
float a[int(f)];
void main()
{
    gl_Position = vec4(0.0);
}
