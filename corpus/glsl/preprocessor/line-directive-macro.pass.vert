// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#line must have, after macro substitution, one of the following two forms: #line line / #line line source-string-number where line and source-string-number are constant integer expressions." ("after macro substitution")
#version 110
#define START 50
#define STRING 3
#line START STRING
#if __LINE__ != 51 || __FILE__ != 3
#error #line with macros not applied
#endif
void main()
{
    gl_Position = vec4(0.0);
}
