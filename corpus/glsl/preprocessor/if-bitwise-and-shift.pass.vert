// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||) (allowed in the preprocessor although reserved in the language)
#version 110
#if (1 << 4) != 16 || (256 >> 4) != 16
#error shift
#endif
#if (6 & 3) != 2 || (6 ^ 3) != 5 || (6 | 3) != 7
#error bitwise
#endif
void main()
{
    gl_Position = vec4(0.0);
}
