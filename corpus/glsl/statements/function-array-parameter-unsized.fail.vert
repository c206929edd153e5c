// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "When arrays are declared as formal parameters, their size must be included."; 4.1.9: "Arrays declared as formal parameters in a function declaration must specify a size."
float first(float a[])
{
    return a[0];
}
void main()
{
    float v[3];
    v[0] = 1.0; v[1] = 2.0; v[2] = 3.0;
    gl_Position = vec4(first(v));
}
