// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
#version 110
uniform int i;
void main()
{
    float x = i ? 1.0 : 0.0;
    gl_Position = vec4(x);
}
