// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||)
#if ~0 != -1 || -(-1) != 1 || +1 != 1 || !0 != 1 || !5 != 0
#error unary
#endif
void main()
{
    gl_Position = vec4(0.0);
}
