// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.1: unary "!" (precedence 3) binds tighter than "==" (precedence 8), so "!a == b" applies ! to the float a; 5.9: not "operates only on a Boolean expression"
uniform float a;
uniform float b;
void main()
{
    bool r = !a == b;
    gl_Position = vec4(float(r));
}
