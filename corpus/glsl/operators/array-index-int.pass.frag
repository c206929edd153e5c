// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.2: "Arrays elements are accessed using an expression whose type is an integer."
#version 110
uniform float w[4];
uniform int k;
void main()
{
    float s = w[0] + w[k] + w[k + 1] + w[3];
    gl_FragColor = vec4(s);
}
