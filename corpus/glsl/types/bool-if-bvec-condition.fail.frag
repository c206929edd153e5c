// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.2 "Expressions used for conditional jumps (if, for, ?:, while, do-while) must evaluate to the type bool."
// 4.1.2 "It is a genuine Boolean type" (a bvec2 is not of type bool)
uniform bvec2 flags;
void main()
{
    float x = 0.0;
    if (flags)
        x = 1.0;
    gl_FragColor = vec4(x);
}
