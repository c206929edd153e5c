// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||)
#version 110
#if !(1 < 2 && 2 > 1 && 1 <= 1 && 1 >= 1 && 1 == 1 && 1 != 2)
#error relational
#endif
#if !(0 || 1) || (1 && 0)
#error logical
#endif
void main()
{
    gl_Position = vec4(0.0);
}
