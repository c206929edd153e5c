// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.5: "To form an l-value, swizzling must be applied to an l-value of vector type"
#version 110
uniform vec4 a;
void main()
{
    vec4 b = a;
    (b + a).xy = vec2(1.0);
    gl_Position = b;
}
