// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||)
#version 110
#if 1 + 2 != 3 || 5 - 7 != -2 || 6 * 7 != 42 || 7 / 2 != 3 || 7 % 4 != 3
#error arithmetic
#endif
void main()
{
    gl_Position = vec4(0.0);
}
