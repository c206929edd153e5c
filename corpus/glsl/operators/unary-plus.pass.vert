// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 9: "unary_operator: PLUS | DASH | BANG | TILDE // reserved"; 5.1: "unary (tilde is reserved) + - ~ !"
#version 110
uniform vec3 v;
uniform int i;
void main()
{
    gl_Position = vec4(+v, float(+i));
}
