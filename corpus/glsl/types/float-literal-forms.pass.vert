// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.4 "floating-constant : fractional-constant exponent-part(opt) / digit-sequence exponent-part"
// 4.1.4 "exponent-part : e sign(opt) digit-sequence / E sign(opt) digit-sequence"
// 4.1.4 "A decimal point ( . ) is not needed if the exponent part is present."
#version 110
void main()
{
    float a = 1.5;
    float b = 1.;
    float c = .5;
    float d = 1e3;
    float e = 1E3;
    float f = 1.5e-3;
    float g = 2.E+2;
    float h = .5e1;
    float i = 00.5;
    float j = 0.0;
    float k = 1e+0;
    float l = 3.402823e38;
    gl_Position = vec4(a + b + c + d, e + f + g + h, i + j + k, l);
}
