// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: "bvec equal(vec x, vec y)", "bvec equal(ivec x, ivec y)", "bvec equal(bvec x, bvec y)" (both arguments of the same type)
uniform vec2 a;
uniform ivec2 b;
void main()
{
    bvec2 r = equal(a, b);
    gl_Position = vec4(float(r.x));
}
