// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.4: "The return jump causes immediate exit of the current function. If it has expression then that is the return value for the function."
uniform float u;
float clip01(float x)
{
    if (x < 0.0)
        return 0.0;
    if (x > 1.0)
        return 1.0;
    return x;
}
void noop()
{
    return;
}
void main()
{
    noop();
    gl_FragColor = vec4(clip01(u));
}
