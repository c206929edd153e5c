// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.1.7: "Samplers cannot be treated as l-values; hence cannot be used as out or inout function parameters"
#version 120
void pick(out sampler2D s, sampler2D a) { s = a; }
uniform sampler2D tex;
void main()
{
    gl_FragColor = texture2D(tex, vec2(0.5));
}
