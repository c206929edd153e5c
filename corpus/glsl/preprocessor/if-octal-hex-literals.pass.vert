// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "Expressions following #if and #elif are restricted to expressions operating on literal integer constants, plus identifiers consumed by the defined operator."
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors."
#version 110
#if 010 != 8 || 0x10 != 16 || 0XfF != 255
#error integer literal forms
#endif
void main()
{
    gl_Position = vec4(0.0);
}
