// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member types must be either already defined (there are no forward references), or defined in-place by embedding another struct definition."
// 4.1.8 "A name given to an embedded struct is scoped at the same level as the struct it is embedded in."
#version 110
struct Outer {
    struct Inner {
        float x;
    } inner;
    float y;
};
Inner standalone;
void main()
{
    Outer o;
    o.inner.x = 1.0;
    o.y = 2.0;
    standalone = o.inner;
    gl_Position = vec4(standalone.x, o.y, 0.0, 1.0);
}
