// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.3 "An integral constant expression can be one of ... an expression whose operands are integral constant expressions" (the comma operator among them, and a const int so initialized)
#version 110
void main()
{
    const int n = (1, 2);
    float a[n];
    a[0] = 1.0;
    a[1] = 2.0;
    gl_Position = vec4(a[0], a[1], 0.0, 1.0);
}
