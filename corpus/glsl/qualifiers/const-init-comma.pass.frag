// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.2 "Initializers for const declarations must be formed from literal values, other const variables (not including function call paramaters), or expressions of these." 5.9 lists the sequence operator among the operators: a comma of constants is an expression of these.
#version 110
struct S { float f; vec2 v; };
void main()
{
    const vec4 v = (vec4(1.0), vec4(2.0, 3.0, 4.0, 5.0));
    const S s = (S(1.0, vec2(2.0)), S(3.0, vec2(4.0)));
    const float f = (v.x, s.f) * 2.0;
    gl_FragColor = v + vec4(s.v, f, 1.0);
}
