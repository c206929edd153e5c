// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "If functions' names and argument types match, then their return type and parameter qualifiers must also match."
#version 110
float f(float x) { return x; }
int f(float x) { return int(x); }
void main()
{
    gl_Position = vec4(f(1.0));
}
