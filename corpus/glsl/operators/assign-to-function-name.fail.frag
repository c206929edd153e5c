// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "function names ... cannot be l-values."
#version 110
float f()
{
    return 1.0;
}
void main()
{
    f = 2.0;
    gl_FragColor = vec4(f());
}
