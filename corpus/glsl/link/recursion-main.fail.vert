// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1.1: "a function may not call itself either directly or indirectly." (main is a function too)
#version 110
uniform bool again;
void main()
{
    gl_Position = vec4(0.0);
    if (again)
        main();
}
