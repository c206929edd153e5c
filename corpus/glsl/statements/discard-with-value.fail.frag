// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "jump_statement: ... DISCARD SEMICOLON"
void main()
{
    gl_FragColor = vec4(1.0);
    discard 1;
}
