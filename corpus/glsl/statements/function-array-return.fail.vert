// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "Arrays are allowed as arguments, but not as the return type."
float[2] pair()
{
    float a[2];
    a[0] = 1.0; a[1] = 2.0;
    return a;
}
void main()
{
    gl_Position = vec4(1.0);
}
