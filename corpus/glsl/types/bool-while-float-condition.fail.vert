// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
#version 110
void main()
{
    float x = 4.0;
    while (x)
        x -= 1.0;
    gl_Position = vec4(x);
}
