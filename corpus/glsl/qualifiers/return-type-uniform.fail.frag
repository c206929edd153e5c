// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Function return types and structure fields do not use qualifiers."
uniform float one()
{
    return 1.0;
}
void main()
{
    gl_FragColor = vec4(one());
}
