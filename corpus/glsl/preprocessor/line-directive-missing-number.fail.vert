// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#line must have, after macro substitution, one of the following two forms: #line line / #line line source-string-number where line and source-string-number are constant integer expressions."
#version 110
#line
void main()
{
    gl_Position = vec4(0.0);
}
