// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "Expressions following #if and #elif are restricted to expressions operating on literal integer constants, plus identifiers consumed by the defined operator."
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors." (macros are expanded in #if)
#version 110
#define N 3
#define TWICE(x) ((x) * 2)
#if TWICE(N) != 6
#error expansion
#endif
void main()
{
    gl_Position = vec4(0.0);
}
