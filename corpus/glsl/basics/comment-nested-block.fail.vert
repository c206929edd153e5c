// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.4 "The begin comment delimiters (/* or //) are not recognized as comment delimiters inside of a comment, hence comments cannot be nested."
#version 110
/* outer /* inner */ trailing words are code */
void main()
{
    gl_Position = vec4(0.0);
}
