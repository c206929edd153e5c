// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "To form an r-value, it can be applied to any expression that results in a vector r-value." A float is not a vector.
#version 110
uniform float f;
void main()
{
    float g = f.x;
    gl_Position = vec4(g);
}
