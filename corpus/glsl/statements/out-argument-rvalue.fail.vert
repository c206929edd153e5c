// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "When calling a function, expressions that do not evaluate to l-values cannot be passed to parameters declared as out or inout."
void set1(out float x) { x = 1.0; }
void main()
{
    float a = 0.0;
    set1(a + 1.0);
    gl_Position = vec4(a);
}
