// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "__LINE__ will substitute a decimal integer constant that is one more than the number of preceding new-lines in the current source string."
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#version 110
#if __LINE__ == 8
#error __LINE__ has the expected value, so this shader is ill-formed
#endif
void main()
{
    gl_Position = vec4(0.0);
}
