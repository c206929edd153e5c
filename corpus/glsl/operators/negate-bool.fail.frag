// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The arithmetic unary operators negate (-) ... operate on integer or floating-point values (including vectors and matrices)."
#version 110
uniform bool b;
void main()
{
    bool c = -b;
    gl_FragColor = vec4(float(c));
}
