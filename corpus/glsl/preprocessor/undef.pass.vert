// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters."
#version 110
#define VALUE 1.0
#undef VALUE
#define VALUE vec4(2.0)
void main()
{
    gl_Position = VALUE;
}
