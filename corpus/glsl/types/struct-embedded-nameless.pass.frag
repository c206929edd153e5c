// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member types must be either already defined (there are no forward references), or defined in-place by embedding another struct definition."
// 4.1.8 "embedded-struct-definition: struct name(opt) { member-list } declarator;"
struct Outer {
    struct {
        float x;
    } inner;
    float y;
};
void main()
{
    Outer o;
    o.inner.x = 1.0;
    o.y = 2.0;
    gl_FragColor = vec4(o.inner.x, o.y, 0.0, 1.0);
}
