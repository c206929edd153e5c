// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The two operands must be the same type, or one can be a scalar float and the other a float vector or matrix, or one can be a scalar integer and the other an integer vector."
uniform float f;
void main()
{
    float g = f + 1;
    gl_Position = vec4(g);
}
