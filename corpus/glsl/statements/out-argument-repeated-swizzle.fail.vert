// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "expressions that do not evaluate to l-values cannot be passed to parameters declared as out or inout."; 5.8: "swizzles with repeated fields ... cannot be l-values."
void set2(out vec2 v) { v = vec2(1.0, 2.0); }
void main()
{
    vec4 p = vec4(0.0);
    set2(p.xx);
    gl_Position = p;
}
