// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Structures must have at least one member declaration."
#version 110
struct Empty {
};
void main()
{
    gl_Position = vec4(0.0);
}
