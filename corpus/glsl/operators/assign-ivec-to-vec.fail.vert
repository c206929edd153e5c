// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "It will compile only if expression and lvalue have the same type. All desired type-conversions must be specified explicitly via a constructor."
#version 110
uniform ivec2 a;
void main()
{
    vec2 v;
    v = a;
    gl_Position = vec4(v, 0.0, 1.0);
}
