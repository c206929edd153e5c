// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "selection_rest_statement: statement ELSE statement | statement" (ELSE only follows an if statement)
#version 110
void main()
{
    gl_FragColor = vec4(0.0);
    else
        gl_FragColor = vec4(1.0);
}
