// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.1 "3.6 ... clarified that the listed keywords and reserved words are the only ones."
// 9 grammar: a precision statement is not a declaration of 1.10
#version 110
precision highp float;
void main()
{
    gl_Position = vec4(0.0);
}
