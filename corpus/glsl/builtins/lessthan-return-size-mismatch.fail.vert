// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: "In all cases, the sizes of the input and return vectors for any particular call must match."
uniform vec4 a;
uniform vec4 b;
void main()
{
    bvec2 r = lessThan(a, b);
    gl_Position = vec4(float(r.x));
}
