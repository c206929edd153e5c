// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||) (?: is not in the list)
#version 110
#if 1 ? 0 : 1
#error unreachable
#endif
void main()
{
    gl_Position = vec4(0.0);
}
