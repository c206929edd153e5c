// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.8: "Variables that are built-in types, entire structures, structure fields ... are all l-values."; 5.7: assignment is "valid if the two operands' types are of the same declared structure" (no exception for structures with array fields)
#version 110
struct S {
    float a[2];
};
void main()
{
    S s;
    S t;
    s.a[0] = 1.0;
    s.a[1] = 2.0;
    t = s;
    gl_FragColor = vec4(t.a[0], t.a[1], 0.0, 1.0);
}
