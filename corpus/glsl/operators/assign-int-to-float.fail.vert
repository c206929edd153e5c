// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "It will compile only if expression and lvalue have the same type. All desired type-conversions must be specified explicitly via a constructor."
#version 110
void main()
{
    float f;
    f = 1;
    gl_Position = vec4(f);
}
