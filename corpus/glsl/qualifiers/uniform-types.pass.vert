// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.5 "The uniform qualifier can be used with any of the basic data types, or when declaring a variable whose type is a structure, or an array of any of these."
#version 110
struct Material {
    vec4 color;
    float shininess[2];
};
uniform bool b;
uniform int i;
uniform float f;
uniform vec2 v2;
uniform vec3 v3;
uniform vec4 v4;
uniform bvec2 bv2;
uniform bvec3 bv3;
uniform bvec4 bv4;
uniform ivec2 iv2;
uniform ivec3 iv3;
uniform ivec4 iv4;
uniform mat2 m2;
uniform mat3 m3;
uniform mat4 m4;
uniform sampler2D s2;
uniform Material material;
uniform Material materials[2];
uniform vec4 lightPosition[4];
void main()
{
    vec4 p = m4 * v4 + vec4(m3 * v3, f) + vec4(m2 * v2, float(i), 1.0);
    p += float(iv2.x + iv3.y + iv4.z) * material.color * materials[1].shininess[1];
    if (b && bv2.x && bv3.y && bv4.z)
        p += lightPosition[3] + texture2D(s2, v2);
    gl_Position = p;
}
