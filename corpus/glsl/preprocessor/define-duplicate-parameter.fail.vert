// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: parameter names of a macro must be unique)
#version 110
#define PICK(a, a) (a)
void main()
{
    gl_Position = vec4(0.0);
}
