// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "struct-definition : qualifier(opt) struct name(opt) { member-list } declarators(opt) ;"
// 4.1.8 "To declare variables of the new type, use its name (without the keyword struct)."
#version 110
struct light {
    float intensity;
    vec3 position;
} lightVar;
light lightVar2;
void main()
{
    lightVar.intensity = 1.0;
    lightVar2 = lightVar;
    gl_Position = vec4(lightVar2.position, lightVar2.intensity);
}
