// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.2 and 5.7: subscripted array names and field selection compose ("postfix_expression LEFT_BRACKET integer_expression RIGHT_BRACKET", "postfix_expression DOT FIELD_SELECTION")
#version 110
struct Light {
    vec3 dir;
    float power[2];
};
uniform Light lights[2];
uniform int k;
void main()
{
    gl_FragColor = vec4(lights[k].dir.zyx, lights[1].power[k]);
}
