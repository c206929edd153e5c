// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "an exact match for the function's signature is sought ... No promotion or demotion of the return type or input argument types is done."
#version 110
float half1(float x)
{
    return x * 0.5;
}
void main()
{
    gl_Position = vec4(half1(1));
}
