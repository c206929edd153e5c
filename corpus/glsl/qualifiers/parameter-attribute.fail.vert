// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Function parameters can only use the in, out, inout, or const qualifiers."
float f(attribute float a)
{
    return a;
}
void main()
{
    gl_Position = vec4(0.0);
}
