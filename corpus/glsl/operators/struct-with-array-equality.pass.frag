// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.7: "When using the equality operators, two structures are equal if and only if all the fields are component-wise equal." (no exception for array fields)
struct S {
    float a[2];
};
uniform S u;
uniform S v;
void main()
{
    bool e = u == v;
    gl_FragColor = vec4(float(e));
}
