// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
void main()
{
    float x = 0.0;
    for (int i = 3; i; --i)
        x += 1.0;
    gl_FragColor = vec4(x);
}
