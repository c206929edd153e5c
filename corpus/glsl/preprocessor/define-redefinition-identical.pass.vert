// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: an identical redefinition is allowed)
#version 110
#define SCALE(x) ((x) * 2.0)
#define SCALE(x) ((x) * 2.0)
#define ONE 1.0
#define ONE 1.0
void main()
{
    gl_Position = vec4(SCALE(ONE));
}
