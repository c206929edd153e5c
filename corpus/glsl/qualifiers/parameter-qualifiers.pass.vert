// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3 "Function parameters can only use the in, out, inout, or const qualifiers."
#version 110
void f(in float a, out float b, inout float c, const float d, const in float e, float g)
{
    b = a + d + e + g;
    c += b;
}
void main()
{
    float b;
    float c = 1.0;
    f(1.0, b, c, 2.0, 3.0, 4.0);
    gl_Position = vec4(b, c, 0.0, 1.0);
}
