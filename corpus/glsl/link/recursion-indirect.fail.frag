// [config]
// expect_result: fail
// glsl_version: 1.10
// check_link: true
// [end config]
// Section 6.1.1: "a function may not call itself either directly or indirectly."
float odd(float n);
float even(float n)
{
    if (n <= 0.0)
        return 1.0;
    return odd(n - 1.0);
}
float odd(float n)
{
    if (n <= 0.0)
        return 0.0;
    return even(n - 1.0);
}
void main()
{
    gl_FragColor = vec4(even(4.0));
}
