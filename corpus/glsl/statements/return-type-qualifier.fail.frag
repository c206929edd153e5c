// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "No qualifier is allowed on the return type of a function."
#version 110
const float one()
{
    return 1.0;
}
void main()
{
    gl_FragColor = vec4(one());
}
