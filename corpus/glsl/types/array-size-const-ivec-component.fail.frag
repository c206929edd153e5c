// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (the operand v of the field selection is a const ivec2, not a scalar integer variable; compare qualifiers/ice-vector-component.pass.frag, where the operand is a constructor of literal integers)
const ivec2 v = ivec2(2, 3);
float a[v.y];
void main()
{
    gl_FragColor = vec4(0.0);
}
