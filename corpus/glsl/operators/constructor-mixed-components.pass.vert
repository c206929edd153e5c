// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "vec3(vec2, float)", "vec3(float, vec2)", "vec4(vec2, vec2)", "bvec4(int, int, float, float)", "vec4(ivec4)"
#version 110
uniform vec2 a;
uniform float f;
uniform ivec4 iv;
void main()
{
    vec3 p = vec3(a, f);
    vec3 q = vec3(f, a);
    vec4 r = vec4(a, a);
    bvec4 b = bvec4(1, 0, 1.0, 0.0);
    vec4 s = vec4(iv);
    gl_Position = vec4(p + q, float(b.x)) + r + s;
}
