// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "When overloaded functions (or indeed any functions) are resolved, an exact match for the function's signature is sought."
float half1(float x)
{
    return x * 0.5;
}
void main()
{
    gl_Position = vec4(half1(float(1)));
}
