// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.1 character set lists no backslash; 3.3 "Each directive is terminated by a new-line." (no line continuation in 1.10: the #else group is compiled, so the error stands)
#version 110
#ifdef NOT_DEFINED
#else
#define SUM(a, b) \
    ((a) + (b))
#endif
void main()
{
    gl_Position = vec4(SUM(1.0, 2.0));
}
