// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: "bvec not(bvec x)" where bvec is bvec2, bvec3 or bvec4 (use ! for a scalar)
#version 110
uniform bool p;
void main()
{
    gl_FragColor = vec4(float(not(p)));
}
