// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.4 "A decimal point ( . ) is not needed if the exponent part is present."
#version 110
void main()
{
    float f = 1e3;
    gl_Position = vec4(f);
}
