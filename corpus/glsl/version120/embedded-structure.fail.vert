// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.1.8: "Anonymous structures are not supported. Embedded structures are not supported." ("struct { ... }; // Error: embedded structures disallowed")
#version 120
struct T {
    struct S { float f; } s;
};
void main()
{
    T t;
    t.s.f = 1.0;
    gl_Position = vec4(t.s.f);
}
