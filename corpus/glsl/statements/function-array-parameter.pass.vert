// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "Arrays are allowed as arguments ... When arrays are declared as formal parameters, their size must be included. An array is passed to a function by using the array name without any subscripting or brackets"
#version 110
float sum(float a[3])
{
    return a[0] + a[1] + a[2];
}
void main()
{
    float v[3];
    v[0] = 1.0; v[1] = 2.0; v[2] = 3.0;
    gl_Position = vec4(sum(v));
}
