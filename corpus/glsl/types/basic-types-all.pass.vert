// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1 "The OpenGL Shading Language supports the following basic data types." (void bool int float vec2-4 bvec2-4 ivec2-4 mat2-4 sampler1D/2D/3D/Cube/1DShadow/2DShadow)
#version 110
uniform sampler1D s1;
uniform sampler2D s2;
uniform sampler3D s3;
uniform samplerCube sc;
uniform sampler1DShadow s1s;
uniform sampler2DShadow s2s;
void main()
{
    bool b = true;
    int i = 1;
    float f = 1.0;
    vec2 v2 = vec2(f);
    vec3 v3 = vec3(f);
    vec4 v4 = vec4(f);
    bvec2 b2 = bvec2(b);
    bvec3 b3 = bvec3(b);
    bvec4 b4 = bvec4(b);
    ivec2 i2 = ivec2(i);
    ivec3 i3 = ivec3(i);
    ivec4 i4 = ivec4(i);
    mat2 m2 = mat2(f);
    mat3 m3 = mat3(f);
    mat4 m4 = mat4(f);
    gl_Position = m4 * v4;
}
