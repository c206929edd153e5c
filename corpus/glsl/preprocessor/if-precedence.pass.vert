// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||) (precedence as in the table)
#version 110
#if 2 + 3 * 4 != 14 || (2 + 3) * 4 != 20 || 1 + 1 << 1 != 4 || (1 | 2 ^ 3 & 1) != 3
#error precedence
#endif
void main()
{
    gl_Position = vec4(0.0);
}
