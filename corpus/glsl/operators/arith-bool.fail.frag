// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: arithmetic binary operators "operate on integer and floating-point typed expressions (including vectors and matrices)."
uniform bool a;
uniform bool b;
void main()
{
    bool c = a + b;
    gl_FragColor = vec4(float(c));
}
