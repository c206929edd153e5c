// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "To declare variables of the new type, use its name (without the keyword struct)."
#version 110
struct light {
    float intensity;
};
struct light lightVar;
void main()
{
    gl_Position = vec4(0.0);
}
