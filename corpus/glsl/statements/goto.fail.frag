// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.4: "There is no "goto" nor other non-structured flow of control."; 3.6 lists goto as reserved
#version 110
void main()
{
    gl_FragColor = vec4(1.0);
    goto end;
}
