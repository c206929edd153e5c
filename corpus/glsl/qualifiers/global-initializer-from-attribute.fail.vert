// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Declarations of globals without a qualifier, or with just the const qualifier may include initializers ... Such initializers must have constant type."
#version 110
attribute vec4 position;
vec4 p = position;
void main()
{
    gl_Position = p;
}
