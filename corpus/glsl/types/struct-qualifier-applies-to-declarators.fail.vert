// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "The optional qualifier only applies to any declarators, and is not part of the type being defined for name."
// 4.3.5 "All uniform variables are read-only"
#version 110
uniform struct Light {
    vec3 position;
    float intensity;
} u_light;
void main()
{
    u_light.intensity = 2.0;
    gl_Position = vec4(u_light.position, 1.0);
}
