// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: the number of arguments must match the parameters)
#version 110
#define SQR(x) ((x) * (x))
void main()
{
    gl_Position = vec4(SQR(1.0, 2.0));
}
