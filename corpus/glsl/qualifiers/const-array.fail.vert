// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "It is an error to write to a const variable outside of its declaration, so they must be initialized when declared."
// 4.1.9 "There is no mechanism for initializing arrays at declaration time from within a shader."
#version 110
const float table[2];
void main()
{
    gl_Position = vec4(0.0);
}
