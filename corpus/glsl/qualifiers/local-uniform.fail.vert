// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Local variables can only use the qualifier const."
#version 110
void main()
{
    uniform float u;
    gl_Position = vec4(u);
}
