// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "array-specifier: empty | [ integral-constant-expression ]"; 4.3.3: an integral constant expression can be "a global or local scalar integer variable qualified as const"
#version 110
const int N = 2;
float sum(float a[N * 2])
{
    return a[0] + a[3];
}
void main()
{
    float v[4];
    v[0] = 1.0; v[1] = 2.0; v[2] = 3.0; v[3] = 4.0;
    gl_FragColor = vec4(sum(v));
}
