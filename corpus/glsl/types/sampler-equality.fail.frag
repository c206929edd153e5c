// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "Samplers are not allowed to be operands in expressions nor can they be assigned into."
uniform sampler2D a;
uniform sampler2D b;
void main()
{
    bool same = a == b;
    gl_FragColor = vec4(same ? 1.0 : 0.0);
}
