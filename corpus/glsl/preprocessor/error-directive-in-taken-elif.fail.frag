// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
// 3.3 "#if, #ifdef, #ifndef, #else, #elif, and #endif are defined to operate as is standard for C++ preprocessors."
#if 0
#elif 1
#error reached through #elif
#endif
void main()
{
    gl_FragColor = vec4(0.0);
}
