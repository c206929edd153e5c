// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: redefining a macro with a different replacement list is ill-formed)
#version 110
#define ONE 1.0
#define ONE 2.0
void main()
{
    gl_Position = vec4(ONE);
}
