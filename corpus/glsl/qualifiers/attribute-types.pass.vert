// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.4 "The attribute qualifier can be used only with the data types float, vec2, vec3, vec4, mat2, mat3, and mat4."
// 4.3.4 "attribute vec4 position; attribute vec3 normal; attribute vec2 texCoord;"
#version 110
attribute float f;
attribute vec2 texCoord;
attribute vec3 normal;
attribute vec4 position;
attribute mat2 m2;
attribute mat3 m3;
attribute mat4 m4;
void main()
{
    vec4 p = m4 * position;
    p.xyz += m3 * normal;
    p.xy += m2 * texCoord;
    gl_Position = p * f;
}
