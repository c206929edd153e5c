// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4: "It is an error to include so many arguments to a constructor that they cannot all be used."
#version 110
void main()
{
    vec2 v = vec2(1.0, 2.0, 3.0);
    gl_Position = vec4(v, 0.0, 1.0);
}
