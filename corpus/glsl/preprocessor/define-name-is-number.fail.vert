// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (a macro name must be an identifier)
#define 3 4
void main()
{
    gl_Position = vec4(0.0);
}
