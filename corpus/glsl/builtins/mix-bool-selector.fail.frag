// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "mix (genType x, genType y, genType a)" and "mix (genType x, genType y, float a)" (the boolean-selector mix is GLSL 1.30)
uniform vec2 a;
uniform vec2 b;
void main()
{
    gl_FragColor = vec4(mix(a, b, bvec2(true, false)), 0.0, 1.0);
}
