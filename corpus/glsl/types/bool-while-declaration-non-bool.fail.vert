// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
// 9 "condition: expression / fully_specified_type IDENTIFIER EQUAL initializer"
#version 110
void main()
{
    float x = 0.0;
    while (float y = 2.0 - x)
        x += 1.0;
    gl_Position = vec4(x);
}
