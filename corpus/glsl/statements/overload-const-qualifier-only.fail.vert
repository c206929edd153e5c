// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "If functions' names and argument types match, then their return type and parameter qualifiers must also match." (const is a parameter qualifier, 6.1.1)
#version 110
float f(const float x) { return x; }
float f(float x) { return x + 1.0; }
void main()
{
    gl_Position = vec4(f(1.0));
}
