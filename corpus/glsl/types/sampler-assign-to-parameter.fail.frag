// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "Samplers are not allowed to be operands in expressions nor can they be assigned into."
uniform sampler2D a;
uniform sampler2D b;
vec4 fetch(sampler2D s, sampler2D t)
{
    s = t;
    return texture2D(s, vec2(0.5));
}
void main()
{
    gl_FragColor = fetch(a, b);
}
