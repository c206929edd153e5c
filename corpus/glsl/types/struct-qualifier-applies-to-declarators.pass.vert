// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "The optional qualifier only applies to any declarators, and is not part of the type being defined for name."
#version 110
uniform struct Light {
    vec3 position;
    float intensity;
} u_light;
void main()
{
    Light local = u_light;
    local.intensity = 2.0;
    gl_Position = vec4(local.position, local.intensity);
}
