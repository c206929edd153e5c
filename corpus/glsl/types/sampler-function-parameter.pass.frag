// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.7 "They can only be declared as function parameters or uniforms"
// 4.1.7 "As function parameters, only samplers may be passed to samplers of matching type."
uniform sampler2D tex;
uniform sampler2DShadow depth;
vec4 fetch(sampler2D s, vec2 uv)
{
    return texture2D(s, uv);
}
vec4 compare(sampler2DShadow s, vec3 uvr)
{
    return shadow2D(s, uvr);
}
void main()
{
    gl_FragColor = fetch(tex, vec2(0.5)) + compare(depth, vec3(0.5));
}
