// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.4 "Comments are delimited by /* and */, or by // and a new-line."
#version 110
void main()
{
    // float hidden = 1.0;
    gl_Position = vec4(hidden);
}
