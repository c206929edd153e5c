// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6: "Simple declaration, expression, and jump statements end in a semi-colon."
void main()
{
    float a = 1.0
    gl_Position = vec4(a);
}
