// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "Any directive not listed above will cause a diagnostic message and make the implementation treat the shader as ill-formed."
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors." (directives in a skipped group are not processed)
#version 110
#if 0
#include <common>
#warning skipped
#endif
void main()
{
    gl_Position = vec4(0.0);
}
