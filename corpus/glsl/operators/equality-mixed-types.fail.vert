// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The two operands must be the same type" (no implicit int->float conversion in 1.10)
uniform float f;
void main()
{
    bool e = f == 1;
    gl_Position = vec4(float(e));
}
