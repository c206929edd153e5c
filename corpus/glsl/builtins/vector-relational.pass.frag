// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.6: "bvec lessThan(vec x, vec y)", "lessThanEqual", "greaterThan", "greaterThanEqual(ivec x, ivec y)", "bvec equal(bvec x, bvec y)", "notEqual", "bool any(bvec x)", "bool all(bvec x)", "bvec not(bvec x)"
#version 110
uniform vec3 a;
uniform vec3 b;
uniform ivec2 i;
uniform ivec2 j;
uniform bvec4 p;
void main()
{
    bvec3 r = lessThan(a, b);
    bvec3 s = lessThanEqual(a, b);
    bvec3 t = greaterThan(a, b);
    bvec2 u = greaterThanEqual(i, j);
    bvec2 v = equal(i, j);
    bvec4 w = notEqual(p, not(p));
    bvec3 x = equal(r, s);
    bool k = any(t) || all(u) || any(v) || all(w) || any(x) || any(notEqual(a, b));
    gl_FragColor = vec4(float(k));
}
