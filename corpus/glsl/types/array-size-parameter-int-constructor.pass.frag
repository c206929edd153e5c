// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "Arrays declared as formal parameters in a function declaration must specify a size."
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (int(3) is a constructor of a literal integer value)
float first(float a[int(3)])
{
    return a[0];
}
void main()
{
    float v[3];
    v[0] = v[1] = v[2] = 1.0;
    gl_FragColor = vec4(first(v));
}
