// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.2 "Structure variables can be declared as const, and initialized with a structure constructor."
#version 110
struct light {
    float intensity;
    vec3 position;
};
const light defaultLight = light(1.0, vec3(0.0, 1.0, 0.0));
void main()
{
    const light local = light(0.5, vec3(1.0));
    gl_Position = vec4(defaultLight.position * local.intensity, 1.0);
}
