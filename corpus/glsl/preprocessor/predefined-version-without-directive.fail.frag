// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "__VERSION__ will substitute a decimal integer reflecting the version number ... __VERSION__ substitute the decimal integer 110."
// 3.3 "shaders that do not include a #version directive will be treated as targeting version 110."
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#if __VERSION__ == 110
#error __VERSION__ is 110
#endif
void main()
{
    gl_FragColor = vec4(0.0);
}
