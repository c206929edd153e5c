// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.1 "In general, the language's use of this character set is case sensitive."
void main()
{
    gl_FragColor = VEC4(1.0);
}
