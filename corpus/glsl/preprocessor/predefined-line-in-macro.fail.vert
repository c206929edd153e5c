// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "__LINE__ will substitute a decimal integer constant that is one more than the number of preceding new-lines in the current source string." (expanded where the macro is used)
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#define HERE __LINE__

#if HERE == 9
#error HERE has the expected value
#endif
void main()
{
    gl_Position = vec4(0.0);
}
