// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "expressions that do not evaluate to l-values cannot be passed to parameters declared as out or inout."; 5.8: "L-values must be writable"; 4.3.5: "All uniform variables are read-only"
uniform float u;
void set1(out float x) { x = 1.0; }
void main()
{
    set1(u);
    gl_FragColor = vec4(u);
}
