// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (true is a literal bool value, not a literal integer value; so is a const bool)
const bool b = true;
float a[int(true)];
float c[int(b) + 1];
void main()
{
    gl_FragColor = vec4(0.0);
}
