// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "There are no number sign based operators (no #, #@, ##, etc.), nor is there a sizeof operator."
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors." (a skipped group's #define is not processed, so its '#' is no operator; piglit's stringification-in-unreachable-branch.frag)
#version 110
#ifdef NOT_DEFINED
#define VEC4_STRING_PARAM(a, b, c, d) vec4(#a, #b, c, d)
#endif
void main()
{
    gl_FragColor = vec4(0.0);
}
