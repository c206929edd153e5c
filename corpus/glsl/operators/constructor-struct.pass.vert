// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.3: "light lightVar = light(3.0, vec3(1.0, 2.0, 3.0));" and "Structure constructors can be used as initializers or in expressions."
#version 110
struct light {
    float intensity;
    vec3 position;
};
void main()
{
    light lightVar = light(3.0, vec3(1.0, 2.0, 3.0));
    vec3 p = light(1.0, vec3(0.0)).position;
    gl_Position = vec4(lightVar.position + p, lightVar.intensity);
}
