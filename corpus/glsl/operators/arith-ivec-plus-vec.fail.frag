// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "The two operands must be the same type"
uniform ivec2 a;
uniform vec2 b;
void main()
{
    vec2 c = a + b;
    gl_FragColor = vec4(c, 0.0, 1.0);
}
