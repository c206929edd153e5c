// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "Each of the typeN must include a type"; samplers are basic types (type_specifier SAMPLER2D) and may be function parameters
#version 110
uniform sampler2D tex;
vec4 fetch(sampler2D s, vec2 uv)
{
    return texture2D(s, uv);
}
void main()
{
    gl_FragColor = fetch(tex, vec2(0.5));
}
