// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.6: "bool any(bvec x)" where bvec is bvec2, bvec3 or bvec4
uniform bool p;
void main()
{
    gl_Position = vec4(float(any(p)));
}
