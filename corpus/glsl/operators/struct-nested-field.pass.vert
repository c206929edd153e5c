// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.7: "the fields of a structure are also selected using the period ( . )"; 5.5 swizzles apply to a vector field
struct Inner {
    vec3 v;
};
struct Outer {
    Inner i;
    float w[2];
};
uniform Outer o;
void main()
{
    gl_Position = vec4(o.i.v.zyx, o.w[1]);
}
