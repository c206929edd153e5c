// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
void main()
{
    float x = 4.0;
    do {
        x -= 1.0;
    } while (x);
    gl_Position = vec4(x);
}
