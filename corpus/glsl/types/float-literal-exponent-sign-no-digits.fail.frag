// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.4 "exponent-part : e sign(opt) digit-sequence / E sign(opt) digit-sequence"
void main()
{
    float x = 1.5e+;
    gl_FragColor = vec4(x);
}
