// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Local variables can only use the qualifier const."
void main()
{
    in float x = 1.0;
    gl_FragColor = vec4(x);
}
