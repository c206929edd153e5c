// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "The relational operators greater than (>), less than (<), greater than or equal (>=), and less than or equal (<=) operate only on scalar integer and scalar floating-point expressions. The result is scalar Boolean."
uniform float a;
uniform int i;
void main()
{
    bool b = a < 1.0 && a >= 0.0 && i > 2 && i <= 5;
    gl_Position = vec4(float(b));
}
