// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters."
#version 110
#define
void main()
{
    gl_Position = vec4(0.0);
}
