// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "As function parameters, only samplers may be passed to samplers of matching type."
vec4 fetch(sampler2D s)
{
    return texture2D(s, vec2(0.5));
}
void main()
{
    gl_FragColor = fetch(0);
}
