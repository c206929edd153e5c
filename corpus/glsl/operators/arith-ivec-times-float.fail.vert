// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "one can be a scalar integer and the other an integer vector." (ivec2 * float is not allowed)
#version 110
uniform ivec2 v;
void main()
{
    ivec2 w = v * 2.0;
    gl_Position = vec4(float(w.x));
}
