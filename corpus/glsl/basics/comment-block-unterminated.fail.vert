// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.4 "Comments are delimited by /* and */, or by // and a new-line."
#version 110
void main()
{
    gl_Position = vec4(0.0);
}
/* this comment never ends
