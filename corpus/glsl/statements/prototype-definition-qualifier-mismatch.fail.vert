// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "If functions' names and argument types match, then their return type and parameter qualifiers must also match."
#version 110
void get(out float x);
void get(inout float x)
{
    x = 1.0;
}
void main()
{
    float v = 0.0;
    get(v);
    gl_Position = vec4(v);
}
