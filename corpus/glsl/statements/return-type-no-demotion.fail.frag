// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "No promotion or demotion of the return type or input argument types is done."
float one()
{
    return 1;
}
void main()
{
    gl_FragColor = vec4(one());
}
