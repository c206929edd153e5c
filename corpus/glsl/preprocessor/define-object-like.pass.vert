// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters."
#version 110
#define HALF 0.5
#define ORIGIN vec4(0.0, 0.0, 0.0, 1.0)
#define EMPTY
void main()
{
    gl_Position = ORIGIN * HALF EMPTY;
}
