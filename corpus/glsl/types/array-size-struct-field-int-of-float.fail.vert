// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators can contain arrays. Such arrays must have a size specified, and the size must be an integral constant expression that's greater than zero (see Section 4.3.3 "Integral Constant Expressions")."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (the operand 2.0 of the constructor is a float literal)
#version 110
struct S
{
    float m[int(2.0)];
};
uniform S s;
void main()
{
    gl_Position = vec4(s.m[0]);
}
