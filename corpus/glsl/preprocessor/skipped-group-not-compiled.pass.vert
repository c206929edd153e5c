// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors."
#version 110
#if 0
this is not valid GLSL ( ;
#endif
#ifdef NOT_DEFINED
neither is this }
#endif
void main()
{
    gl_Position = vec4(0.0);
}
