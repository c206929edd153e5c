// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "struct-definition : qualifier(opt) struct name(opt) { member-list } declarators(opt) ;" (name is optional)
#version 110
struct {
    float a;
    vec2 b;
} s;
void main()
{
    s.a = 1.0;
    gl_Position = vec4(s.b, s.a, 1.0);
}
