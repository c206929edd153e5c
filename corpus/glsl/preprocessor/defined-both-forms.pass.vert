// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "The defined operator can be used in either of the following ways: defined identifier / defined ( identifier )"
#version 110
#define FOO
#if !defined FOO || !defined(FOO) || !defined ( FOO ) || defined BAR || defined(BAR)
#error defined
#endif
void main()
{
    gl_Position = vec4(0.0);
}
