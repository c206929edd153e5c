// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.5 "The OpenGL Shading Language includes data types for generic 2-, 3-, and 4-component vectors of floating-point values, integers, or Booleans."
// 4.1.5 "vec2 texcoord1, texcoord2; vec3 position; vec4 myRGBA; ivec2 textureLookup; bvec3 lessThan;"
#version 110
void main()
{
    vec2 texcoord1, texcoord2;
    vec3 position;
    vec4 myRGBA;
    ivec2 textureLookup;
    bvec3 lessThan;
    ivec3 i3 = ivec3(1, 2, 3);
    ivec4 i4 = ivec4(i3, 4);
    bvec2 b2 = bvec2(true, false);
    bvec4 b4 = bvec4(b2, b2);
    texcoord1 = vec2(1.0);
    gl_Position = vec4(texcoord1, 0.0, 1.0);
}
