// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.2: "The if statement's expression does not allow new variables to be declared"; 9: "selection_statement: IF LEFT_PAREN expression RIGHT_PAREN selection_rest_statement"
uniform float f;
void main()
{
    gl_Position = vec4(0.0);
    if (bool b = f > 0.5)
        gl_Position = vec4(1.0);
}
