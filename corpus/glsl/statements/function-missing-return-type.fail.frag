// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "Where returnType must be present and include a type."
helper(float x)
{
    return x;
}
void main()
{
    gl_FragColor = vec4(helper(1.0));
}
