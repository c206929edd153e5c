// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors."
#version 110
#if 0
#error not reached
#endif
#ifdef NOT_DEFINED
#error not reached
#endif
void main()
{
    gl_Position = vec4(0.0);
}
