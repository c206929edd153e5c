// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: relational operators: "The operands' types must match."
uniform int i;
void main()
{
    bool c = i < 1.0;
    gl_FragColor = vec4(float(c));
}
