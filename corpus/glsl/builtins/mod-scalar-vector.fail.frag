// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType mod (genType x, float y)" and "genType mod (genType x, genType y)" (there is no mod(float, vec))
uniform float f;
uniform vec2 v;
void main()
{
    gl_FragColor = vec4(mod(f, v), 0.0, 1.0);
}
