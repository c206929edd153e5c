// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: "function_definition" appears only in "external_declaration"; a compound statement cannot contain a function definition
void main()
{
    float inner(float x)
    {
        return x;
    }
    gl_Position = vec4(inner(1.0));
}
