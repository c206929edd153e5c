// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||)
// 3.3 "#error will cause the implementation to put a diagnostic message into the shader's information log ... The implementation must then consider the shader to be ill-formed."
#version 110
#if 2 + 3 * 4 == 14
#error multiplication binds tighter than addition
#endif
void main()
{
    gl_Position = vec4(0.0);
}
