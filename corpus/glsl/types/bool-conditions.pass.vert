// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
#version 110
uniform bool flag;
void main()
{
    float x = 0.0;
    if (flag)
        x = 1.0;
    for (int i = 0; i < 2; ++i)
        x += 1.0;
    while (x > 10.0)
        x -= 1.0;
    do {
        x *= 0.5;
    } while (x > 4.0);
    x = flag ? x : -x;
    gl_Position = vec4(x);
}
