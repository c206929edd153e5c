// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.7: samplers can be declared as function parameters (in parameters: no l-value)
uniform sampler2D tex;
vec4 sample(sampler2D s, vec2 uv) { return texture2D(s, uv); }
void main()
{
    gl_FragColor = sample(tex, vec2(0.5));
}
