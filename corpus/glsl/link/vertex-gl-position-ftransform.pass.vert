// [config]
// expect_result: pass
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 7.1: "All executions of a well-formed vertex shader must write a value into this variable."; 8.4: "gl_Position = ftransform()"
void main()
{
    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
}
