// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators can contain arrays. Such arrays must have a size specified, and the size must be an integral constant expression that's greater than zero (see Section 4.3.3 "Integral Constant Expressions")."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (constructors of integral constant expressions are allowed)
#version 110
const int n = 2;
struct S
{
    float m[int(n)];
    float k[ivec2(n, 3).y];
};
uniform S s;
void main()
{
    gl_Position = vec4(s.m[1] + s.k[2]);
}
