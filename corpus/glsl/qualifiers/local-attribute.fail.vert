// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Local variables can only use the qualifier const."
// 4.3.4 "Attribute variables are required to have global scope, and must be declared outside of function bodies, before their first use."
void main()
{
    attribute vec4 a;
    gl_Position = a;
}
