// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The logical binary operators ... operate only on two Boolean expressions and result in a Boolean expression."
uniform bvec2 a;
uniform bvec2 b;
void main()
{
    bvec2 c = a || b;
    gl_FragColor = vec4(float(c.x));
}
