// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (the local const int n hides the global const float n, so the operand of the constructor is a const int)
// 4.2 "However, a nested scope can override an outer scope's declaration of a particular variable name."
const float n = 2.0;
void main()
{
    const int n = 2;
    float a[int(n)];
    a[1] = float(n);
    gl_FragColor = vec4(a[1]);
}
