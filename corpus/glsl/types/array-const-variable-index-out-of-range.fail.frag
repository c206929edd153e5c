// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls."
const int four = 4;
void main()
{
    vec4 a[4];
    gl_FragColor = a[four];
}
