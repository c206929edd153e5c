// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The logical unary operator not (!). It operates only on a Boolean expression and results in a Boolean expression. To operate on a vector, use the built-in function not."
uniform bvec3 a;
void main()
{
    bvec3 c = !a;
    gl_FragColor = vec4(float(c.x));
}
