// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Structures can be initialized at declaration time using constructors"
#version 110
struct light {
    float intensity;
    vec3 position;
};
void main()
{
    light l = light(3.0, vec3(1.0, 2.0, 3.0));
    gl_Position = vec4(l.position, l.intensity);
}
