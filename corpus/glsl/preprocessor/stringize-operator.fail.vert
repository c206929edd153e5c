// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "There are no number sign based operators (no #, #@, ##, etc.), nor is there a sizeof operator."
#version 110
#define STR(a) #a
float STR(x);
void main()
{
    gl_Position = vec4(0.0);
}
