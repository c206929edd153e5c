// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.7: "the following operators are allowed to operate on a structure: structure field selector . equality == != assignment ="
struct S {
    float a;
    vec2 b;
};
uniform S u;
void main()
{
    S s;
    s = u;
    s.a = 1.0;
    bool e = s == u;
    bool n = s != u;
    gl_FragColor = vec4(s.b, float(e), float(n));
}
