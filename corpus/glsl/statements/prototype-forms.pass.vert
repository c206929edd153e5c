// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "name : empty | identifier"; 9: "parameter_declaration: ... parameter_qualifier parameter_type_specifier", "parameter_type_specifier: type_specifier LEFT_BRACKET constant_expression RIGHT_BRACKET"
#version 110
float first(float[2]);
float mixed(in float, out vec2, inout float);
float first(float a[2])
{
    return a[0];
}
float mixed(in float x, out vec2 y, inout float z)
{
    y = vec2(x);
    z += x;
    return z;
}
void main()
{
    float a[2];
    a[0] = 1.0; a[1] = 2.0;
    vec2 y;
    float z = 0.0;
    gl_Position = vec4(first(a), mixed(1.0, y, z), y);
}
