// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The two operands must be the same type, or one can be a scalar float and the other a float vector or matrix, or one can be a scalar integer and the other an integer vector."
#version 110
uniform float f;
uniform vec3 v;
uniform mat2 m;
uniform ivec2 iv;
uniform int i;
void main()
{
    float g = f + 1.0;
    vec3 a = v * f + f * v - v / f;
    mat2 b = m * f + f - m;
    ivec2 c = iv * i + i - iv / 2;
    int d = i / 2 * 3;
    gl_Position = vec4(a + vec3(g), b[0][0] + float(c.x + d));
}
