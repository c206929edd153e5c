// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "single_declaration: fully_specified_type | ..." (a declaration may consist of a type alone)
void main()
{
    float;
    gl_Position = vec4(1.0);
}
