// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "declaration: function_prototype SEMICOLON | ..." and "declaration_statement: declaration" (a prototype is a legal statement)
#version 110
void main()
{
    float twice(float x);
    gl_Position = vec4(twice(0.5));
}
float twice(float x)
{
    return 2.0 * x;
}
