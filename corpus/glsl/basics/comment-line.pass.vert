// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.4 "Comments are delimited by /* and */, or by // and a new-line."
#version 110 // a comment after a directive
// a full-line comment
void main() // a comment after code
{
    gl_Position = vec4(0.0); // float x = ; garbage here is ignored
}
