// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "array-specifier: [ integral-constant-expression ]"; 4.3.3: an integral constant expression is "a global or local scalar integer variable qualified as const, not including function parameters qualified as const"
#version 110
float f(const int n)
{
    float a[n];
    a[0] = 1.0;
    return a[0];
}
void main()
{
    gl_Position = vec4(f(2));
}
