// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1 "void for functions that do not return a value"
void main()
{
    void nothing;
    gl_FragColor = vec4(0.0);
}
