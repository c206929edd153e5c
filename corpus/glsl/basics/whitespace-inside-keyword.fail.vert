// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.1 "White space: the space character, horizontal tab, vertical tab, form feed, carriage-return, and line-feed." (white space separates tokens)
#version 110
void main()
{
    fl oat x = 1.0;
    gl_Position = vec4(x);
}
