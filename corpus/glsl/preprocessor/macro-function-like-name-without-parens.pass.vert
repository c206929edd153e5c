// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: a function-like macro name not followed by ( is not expanded)
#version 110
#define scale(x) ((x) * 2.0)
float scale = 1.5;
void main()
{
    gl_Position = vec4(scale(scale));
}
