// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.3 "A leading unary minus sign (-) is interpreted as an arithmetic unary negation, not as part of the constant."
#version 110
void main()
{
    int a = -32768;
    int b = -0x10;
    int c = - 010;
    int d = -(-1);
    gl_Position = vec4(float(a + b + c + d));
}
