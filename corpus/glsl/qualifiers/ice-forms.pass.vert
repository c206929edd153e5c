// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.3 "An integral constant expression can be one of: a literal integer value; a global or local scalar integer variable qualified as const, not including function parameters qualified as const; an expression whose operands are integral constant expressions, including constructors, but excluding function calls."
#version 110
const int globalN = 3;
void main()
{
    const int localN = 2;
    float a[4];
    float b[globalN];
    float c[localN];
    float d[globalN * localN + 1];
    float e[int(2)];
    float f[-(-2)];
    a[3] = b[2] = c[1] = d[6] = e[1] = f[1] = 1.0;
    gl_Position = vec4(a[3]);
}
