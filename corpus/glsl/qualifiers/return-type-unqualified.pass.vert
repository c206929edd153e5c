// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3 "Function return types and structure fields do not use qualifiers."
#version 110
float one()
{
    return 1.0;
}
void main()
{
    gl_Position = vec4(one());
}
