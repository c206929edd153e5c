// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.6 "In addition, all identifiers containing two consecutive underscores (__) are reserved as possible future keywords."
float get__value()
{
    return 1.0;
}
void main()
{
    gl_FragColor = vec4(get__value());
}
