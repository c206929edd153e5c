// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.1 the character set lists no backslash (no line continuation in 1.10), but 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors." (a skipped group's text is not processed; every driver accepts it: a warning, glsl-skipped-line-continuation; piglit's if-statement-in-macro-in-false-ifdef.vert)
#version 110
#ifdef NOT_DEFINED
#define A_MACRO(x) \
    if (x)
#endif
void main()
{
    gl_Position = vec4(0.0);
}
