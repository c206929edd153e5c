// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "Samplers are not allowed to be operands in expressions nor can they be assigned into."
uniform sampler2D a;
uniform sampler2D b;
uniform bool pick;
void main()
{
    gl_FragColor = texture2D(pick ? a : b, vec2(0.5));
}
