// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: ternary: "the first expression, which must result in a scalar Boolean."
#version 110
uniform bvec2 p;
void main()
{
    vec2 c = p ? vec2(1.0) : vec2(0.0);
    gl_Position = vec4(c, 0.0, 1.0);
}
