// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (constructors of integral constant expressions are allowed)
void main()
{
    float a[ivec2(2, 3).y];
    a[2] = 1.0;
    gl_FragColor = vec4(a[2]);
}
