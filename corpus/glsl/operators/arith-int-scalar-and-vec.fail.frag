// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "one can be a scalar integer and the other an integer vector" (an int scalar may not combine with a float vector)
uniform vec4 v;
uniform int i;
void main()
{
    gl_FragColor = i + v;
}
