// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "Expressions following #if and #elif are restricted to expressions operating on literal integer constants, plus identifiers consumed by the defined operator." (macros are expanded first; the #if inside the skipped group is not evaluated)
#version 110
#define ONE 1
#define TWO (ONE + ONE)
#if TWO == 2 && defined(ONE) && !defined NOT_A_MACRO
#ifdef NOT_A_MACRO
#if NOT_A_MACRO
#endif
#endif
void main()
{
    gl_Position = vec4(0.0);
}
#endif
