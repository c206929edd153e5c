// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.4: "The break jump can also be used only in loops."
uniform bool p;
void main()
{
    gl_Position = vec4(0.0);
    if (p)
        break;
}
