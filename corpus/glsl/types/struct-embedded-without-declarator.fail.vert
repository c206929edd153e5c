// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Anonymous structures are not supported; so embedded structures must have a declarator."
#version 110
struct Outer {
    struct Inner {
        float x;
    };
    float y;
};
void main()
{
    gl_Position = vec4(0.0);
}
