// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "Other binary or unary expressions ... cannot be l-values."
#version 110
void main()
{
    float a = 1.0;
    float b = 2.0;
    a + b = 3.0;
    gl_FragColor = vec4(a);
}
