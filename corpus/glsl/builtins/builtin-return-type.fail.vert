// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8: "the actual type has to be the same for all arguments and for the return type."
#version 110
uniform vec2 a;
void main()
{
    vec3 s = sin(a);
    gl_Position = vec4(s, 1.0);
}
