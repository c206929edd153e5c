// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4.3: "The arguments to the constructor must be in the same order and of the same type as they were declared in the structure."
struct light {
    float intensity;
    vec3 position;
};
void main()
{
    light lightVar = light(3, vec3(1.0, 2.0, 3.0));
    gl_Position = vec4(lightVar.position, lightVar.intensity);
}
