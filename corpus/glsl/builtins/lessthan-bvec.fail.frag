// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: lessThan is defined for "(vec x, vec y)" and "(ivec x, ivec y)" only; equal and notEqual also take bvec
#version 110
uniform bvec2 a;
uniform bvec2 b;
void main()
{
    bvec2 r = lessThan(a, b);
    gl_FragColor = vec4(float(r.x));
}
