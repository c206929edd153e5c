// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.2: "Arrays elements are accessed using an expression whose type is an integer."
uniform float w[4];
void main()
{
    float s = w[1.0];
    gl_FragColor = vec4(s);
}
