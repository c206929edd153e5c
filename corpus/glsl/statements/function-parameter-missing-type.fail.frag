// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "Each of the typeN must include a type and can optionally include the qualifier in, out, inout, and/or const."
#version 110
float twice(in x)
{
    return 2.0 * x;
}
void main()
{
    gl_FragColor = vec4(twice(1.0));
}
