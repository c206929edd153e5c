// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: a macro is not re-expanded inside its own expansion)
#version 110
float f(float x)
{
    return x * 2.0;
}
#define f(x) f((x) + 1.0)
void main()
{
    gl_Position = vec4(f(1.0));
}
