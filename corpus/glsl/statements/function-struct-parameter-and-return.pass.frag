// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.1: "Structures are also allowed as arguments. The return type can also be structure."
#version 110
struct Pair {
    float a;
    float b;
};
Pair swap(Pair p)
{
    return Pair(p.b, p.a);
}
void main()
{
    Pair q = swap(Pair(1.0, 2.0));
    gl_FragColor = vec4(q.a, q.b, 0.0, 1.0);
}
