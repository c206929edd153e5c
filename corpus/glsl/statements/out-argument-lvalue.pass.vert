// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "When calling a function, expressions that do not evaluate to l-values cannot be passed to parameters declared as out or inout." (variables, swizzles without repeats, array elements and fields are l-values, 5.8)
#version 110
struct S { float f; };
void set2(out vec2 v) { v = vec2(1.0, 2.0); }
void inc(inout float x) { x += 1.0; }
void main()
{
    vec4 p = vec4(0.0);
    float a[2];
    S s;
    s.f = 0.0;
    a[1] = 0.0;
    set2(p.wy);
    inc(a[1]);
    inc(s.f);
    inc(p.x);
    gl_Position = p + vec4(a[1], s.f, 0.0, 0.0);
}
