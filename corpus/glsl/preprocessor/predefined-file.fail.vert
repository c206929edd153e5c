// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "__FILE__ will substitute a decimal integer constant that says which source string number is currently being processed."
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#version 110
#if __FILE__ == 0
#error __FILE__ is 0
#endif
void main()
{
    gl_Position = vec4(0.0);
}
