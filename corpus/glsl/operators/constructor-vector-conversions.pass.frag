// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.4.2: "If the basic type (bool, int, or float) of a parameter to a constructor does not match the basic type of the object being constructed, the scalar construction rules (above) are used to convert the parameters."
uniform vec4 v;
uniform ivec3 iv;
void main()
{
    vec2 a = vec2(true);
    ivec2 b = ivec2(v);
    bvec2 c = bvec2(v);
    vec3 d = vec3(iv);
    bvec3 e = bvec3(iv.x, 0.0, false);
    mat2 m = mat2(1, 0, 0, true);
    mat2 n = mat2(ivec4(1));
    gl_FragColor = vec4(a, float(b.x), float(c.y)) + vec4(d, float(e.x)) + vec4(m[0], n[1]);
}
