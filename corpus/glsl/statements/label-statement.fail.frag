// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "// Grammar Note: No labeled statements; 'goto' is not supported."
void main()
{
    float a = 1.0;
start:
    a = 2.0;
    gl_FragColor = vec4(a);
}
