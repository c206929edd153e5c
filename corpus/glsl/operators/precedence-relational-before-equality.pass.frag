// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.1: relational (precedence 7) binds tighter than equality (precedence 8), so "a < b == c < d" compares two bools
#version 110
uniform float a;
uniform float b;
uniform float c;
uniform float d;
void main()
{
    bool r = a < b == c < d;
    gl_FragColor = vec4(float(r));
}
