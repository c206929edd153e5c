// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "left shift by (<<=), right shift by (>>=) ... These operators are reserved for future use."
uniform int a;
void main()
{
    int c = 6;
    c <<= a;
    gl_FragColor = vec4(float(c));
}
