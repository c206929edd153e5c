// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.4 "The begin comment delimiters (/* or //) are not recognized as comment delimiters inside of a comment, hence comments cannot be nested."
#version 110
/* // this is not a line comment */ float x = 1.0;
void main()
{
    gl_Position = vec4(x);
}
