// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1: "User-defined functions can have multiple declarations, but only one definition." (main declared first and defined later)
void main();
vec4 color()
{
    return vec4(1.0);
}
void main()
{
    gl_FragColor = color();
}
