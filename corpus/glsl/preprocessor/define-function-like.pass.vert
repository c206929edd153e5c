// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters."
#version 110
#define SQR(x) ((x) * (x))
#define ADD(a, b) ((a) + (b))
#define ZERO() 0.0
void main()
{
    float v = ADD(SQR(2.0), ZERO());
    gl_Position = vec4(v);
}
