// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.8: "Variables that are built-in types, entire structures, structure fields, l-values with the field selector ( . ) applied to select components or swizzles without repeated fields, and l-values dereferenced with the array subscript operator ( [ ] ) are all l-values."
#version 110
struct S {
    vec3 v;
    float f;
};
void main()
{
    S s;
    S t;
    float a[2];
    s.v = vec3(1.0);
    s.v.zx = vec2(0.0, 0.5);
    s.f = 2.0;
    a[1] = s.f;
    a[0] = a[1];
    t = s;
    mat2 m;
    m[1][0] = 1.0;
    gl_FragColor = vec4(t.v, a[0] + m[1][0]);
}
