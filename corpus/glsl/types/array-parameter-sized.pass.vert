// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.9 "Arrays declared as formal parameters in a function declaration must specify a size."
#version 110
float sum(float a[3])
{
    return a[0] + a[1] + a[2];
}
void main()
{
    float v[3];
    v[0] = v[1] = v[2] = 1.0;
    gl_Position = vec4(sum(v));
}
