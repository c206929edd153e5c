// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.6 "The varying qualifier can be used only with the data types float, vec2, vec3, vec4, mat2, mat3, and mat4, or arrays of these. Structures cannot be varying."
// 4.1.9 "Variables of the same type can be aggregated into arrays by declaring a name followed by brackets ( [ ] ) enclosing an optional size."
#version 110
varying vec4 extra[];
void main()
{
    extra[1] = vec4(1.0);
    gl_Position = extra[1];
}
