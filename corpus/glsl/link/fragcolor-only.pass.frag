// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.2: "These variables may be written more than once within a fragment shader. If so, the last value assigned is the one used"
void main()
{
    gl_FragColor = vec4(0.0);
    gl_FragColor = vec4(1.0);
}
