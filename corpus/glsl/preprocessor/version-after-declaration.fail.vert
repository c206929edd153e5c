// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "The #version directive must occur in a shader before anything else, except for comments and white space."
float x;
#version 110
void main()
{
    gl_Position = vec4(0.0);
}
