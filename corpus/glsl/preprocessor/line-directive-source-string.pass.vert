// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#line must have, after macro substitution, one of the following two forms: #line line / #line line source-string-number where line and source-string-number are constant integer expressions."
// 3.3 "After processing this directive (including its new-line), the implementation will behave as if it is compiling at line number line+1 and source string number source-string-number."
#version 110
#line 20 7
#if __LINE__ != 21 || __FILE__ != 7
#error #line 20 7 not applied
#endif
void main()
{
    gl_Position = vec4(0.0);
}
