// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "Operators and (&), or ( | ), exclusive or (^), not (~), right-shift (>>), left-shift (<<). These operators are reserved for future use."
uniform int a;
void main()
{
    int c = a >> 1;
    gl_FragColor = vec4(float(c));
}
