// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.3: "Function parameters can only use the in, out, inout, or const qualifiers."; 6.1.1 grammar: "const-qualifier parameter-qualifier type name"
float f(uniform float x)
{
    return x;
}
void main()
{
    gl_Position = vec4(f(1.0));
}
