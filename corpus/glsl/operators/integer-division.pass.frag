// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: divide (/) operates "on integer and floating-point typed expressions"; "These result in the same fundamental type (integer or float)"
uniform int a;
void main()
{
    int q = 7 / 2;
    int r = a / q;
    gl_FragColor = vec4(float(q + r));
}
