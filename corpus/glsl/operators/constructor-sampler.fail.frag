// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 9: constructor_identifier is FLOAT INT BOOL VEC2..4 BVEC2..4 IVEC2..4 MAT2..4 TYPE_NAME; samplers have no constructor
uniform sampler2D s;
void main()
{
    gl_FragColor = texture2D(sampler2D(s), vec2(0.5));
}
