// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "expressions that do not evaluate to l-values cannot be passed to parameters declared as out or inout."; 5.8: "constants cannot be l-values"
#version 110
const float k = 1.0;
void set1(out float x) { x = 1.0; }
void main()
{
    set1(k);
    gl_FragColor = vec4(k);
}
