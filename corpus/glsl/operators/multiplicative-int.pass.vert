// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.9: "add (+), subtract (-), multiply (*), and divide (/), that operate on integer and floating-point typed expressions"
uniform int a;
uniform int b;
void main()
{
    int c = a * b / 3 - a + b;
    gl_Position = vec4(float(c));
}
