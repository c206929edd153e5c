// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "The defined operator can be used in either of the following ways: defined identifier / defined ( identifier )" (the operand must be an identifier)
#if defined 3
#endif
void main()
{
    gl_FragColor = vec4(0.0);
}
