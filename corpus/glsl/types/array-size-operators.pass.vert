// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls." (operators of literal integers and const int variables)
#version 110
const int n = 2;
float a[2 + 1];
float b[n * 2];
float c[-(-n) + int(3) * (4 / 2)];
void main()
{
    float d[n - 1];
    a[2] = b[3] = c[7] = d[0] = 1.0;
    gl_Position = vec4(a[2]);
}
