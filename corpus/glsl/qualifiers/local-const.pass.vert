// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3 "Local variables can only use the qualifier const."
#version 110
void main()
{
    const float halfValue = 0.5;
    const vec4 color = vec4(halfValue, halfValue, 1.0, 1.0);
    gl_Position = color;
}
