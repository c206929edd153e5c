// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.1: "vec4 gl_Position;"; 5.8: assignment "will compile only if expression and lvalue have the same type."
#version 110
void main()
{
    gl_Position = vec3(1.0);
}
