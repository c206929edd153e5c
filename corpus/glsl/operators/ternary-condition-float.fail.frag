// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: ternary: "This operator evaluates the first expression, which must result in a scalar Boolean."
uniform float f;
void main()
{
    float c = f ? 1.0 : 0.0;
    gl_FragColor = vec4(c);
}
