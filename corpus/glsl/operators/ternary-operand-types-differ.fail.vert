// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: ternary: "The second and third expressions must be the same type"
uniform bool p;
void main()
{
    float c = p ? 1.0 : 0;
    gl_Position = vec4(c);
}
