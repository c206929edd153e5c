// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: #undef of a name that is not defined is ignored)
#undef NEVER_DEFINED
void main()
{
    gl_Position = vec4(0.0);
}
