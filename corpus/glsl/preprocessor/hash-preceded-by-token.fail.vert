// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Each number sign (#) can be preceded in its line only by spaces or horizontal tabs."
#version 110
float a = 1.0; #define B 2.0
void main()
{
    gl_Position = vec4(0.0);
}
