// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "The keyword in ... out ... inout ... A function parameter declared with no such qualifier means the same thing as specifying in."; "const-qualifier parameter-qualifier type name"
#version 110
void f(float a, in float b, const float c, const in float d, out float e, inout float g)
{
    e = a + b + c + d;
    g = g * 2.0;
}
void main()
{
    float e;
    float g = 1.0;
    f(1.0, 2.0, 3.0, 4.0, e, g);
    gl_Position = vec4(e, g, 0.0, 1.0);
}
