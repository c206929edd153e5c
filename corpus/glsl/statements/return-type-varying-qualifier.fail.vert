// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "No qualifier is allowed on the return type of a function."
varying float v;
varying float get()
{
    return 1.0;
}
void main()
{
    v = get();
    gl_Position = vec4(v);
}
