// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "selection_statement: IF LEFT_PAREN expression RIGHT_PAREN selection_rest_statement"
#version 110
uniform bool p;
void main()
{
    gl_Position = vec4(0.0);
    if p
        gl_Position = vec4(1.0);
}
