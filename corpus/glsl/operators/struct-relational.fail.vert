// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.7: only ". == != =" operate on structures; 5.9: relational operators "operate only on scalar integer and scalar floating-point expressions"
struct S {
    float a;
};
uniform S u;
uniform S v;
void main()
{
    bool b = u < v;
    gl_Position = vec4(float(b));
}
