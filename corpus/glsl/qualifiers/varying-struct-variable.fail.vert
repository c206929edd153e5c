// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 4.3.6: "The varying qualifier can be used only with the data types float, vec2, vec3,
// vec4, mat2, mat3, and mat4, or arrays of these. Structures cannot be varying."
varying struct Light {
    float intensity;
} light;
void main()
{
    gl_Position = vec4(0.0);
}
