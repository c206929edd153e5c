// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1.1: "When calling a function, expressions that do not evaluate to l-values cannot be passed to parameters declared as out or inout."
#version 110
void inc(inout float x) { x += 1.0; }
void main()
{
    inc(1.0);
    gl_FragColor = vec4(1.0);
}
