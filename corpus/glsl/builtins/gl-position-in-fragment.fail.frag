// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.1: "The variable gl_Position is available only in the vertex language"
void main()
{
    gl_FragColor = gl_Position;
}
