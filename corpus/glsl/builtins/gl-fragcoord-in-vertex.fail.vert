// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "The variable gl_FragCoord is available as a read-only variable from within fragment shaders"
void main()
{
    gl_Position = gl_FragCoord;
}
