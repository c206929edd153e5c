// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.8: "lvalue op= expression ... the l-value and expression must satisfy the semantic requirements of both op and equals (=)"; "swizzles with repeated fields ... cannot be l-values."
#version 110
void main()
{
    vec4 v = vec4(0.0);
    v.yy += vec2(1.0);
    gl_Position = v;
}
