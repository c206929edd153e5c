// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "The operators available are" (table: () defined + - ~ ! * / % + - << >> < > <= >= == != & ^ | && ||)
#if 1 ||
#endif
void main()
{
    gl_FragColor = vec4(0.0);
}
