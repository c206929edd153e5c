// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.3 "There are no letter suffixes."
void main()
{
    int i = 0x10U;
    gl_FragColor = vec4(float(i));
}
