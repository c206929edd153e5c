// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "array-specifier: empty | [ integral-constant-expression ]"
uniform int n;
float first(float a[n])
{
    return a[0];
}
void main()
{
    gl_FragColor = vec4(1.0);
}
