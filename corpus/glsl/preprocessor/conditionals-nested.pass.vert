// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors."
#version 110
#define A
#ifdef A
#  ifndef B
#    if 0
#      error skipped
#    elif 1
float value = 1.0;
#    else
#      error skipped
#    endif
#  else
#    error skipped
#  endif
#else
#  error skipped
#endif
void main()
{
    gl_Position = vec4(value);
}
