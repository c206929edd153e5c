// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (2e0 has an exponent: 4.1.4 makes it a float literal, so it is not a literal integer value; the first declarator b[int(3)] is fine)
// 4.1.4 "floating-constant : fractional-constant exponent-part_opt / digit-sequence exponent-part"
#version 110
float b[int(3)], a[int(2e0)];
void main()
{
    gl_Position = vec4(0.0);
}
