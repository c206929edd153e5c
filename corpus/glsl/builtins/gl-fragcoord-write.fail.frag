// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "The variable gl_FragCoord is available as a read-only variable from within fragment shaders"
void main()
{
    gl_FragCoord = vec4(0.0);
    gl_FragColor = vec4(1.0);
}
