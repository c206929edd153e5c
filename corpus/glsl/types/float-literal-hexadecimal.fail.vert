// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.4 "floating-constant : fractional-constant exponent-part(opt) / digit-sequence exponent-part"
#version 110
void main()
{
    float x = 0x1.8p1;
    gl_Position = vec4(x);
}
