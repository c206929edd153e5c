// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "There are no number sign based operators (no #, #@, ##, etc.), nor is there a sizeof operator." (macros without # or ## work)
#version 110
#define DECLARE(type, name, value) type name = value
void main()
{
    DECLARE(vec4, p, vec4(1.0));
    gl_Position = p;
}
