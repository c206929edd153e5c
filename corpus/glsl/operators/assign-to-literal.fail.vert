// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "constants cannot be l-values."
void main()
{
    1.0 = 2.0;
    gl_Position = vec4(1.0);
}
