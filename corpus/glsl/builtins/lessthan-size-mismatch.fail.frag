// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: "In all cases, the sizes of the input and return vectors for any particular call must match."
#version 110
uniform vec2 a;
uniform vec3 b;
void main()
{
    bvec2 r = lessThan(a, b.xy);
    bvec3 s = lessThan(a, b);
    gl_FragColor = vec4(float(r.x), float(s.x), 0.0, 1.0);
}
