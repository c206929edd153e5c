// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.4: "It is an error to include so many arguments to a constructor that they cannot all be used."
void main()
{
    float f = float(1.0, 2.0);
    gl_Position = vec4(f);
}
