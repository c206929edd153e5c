// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Local variables can only use the qualifier const."
// 4.3.6 "Varying variables are required to have global scope, and must be declared outside of function bodies, before their first use."
#version 110
void main()
{
    varying vec4 v;
    v = vec4(1.0);
    gl_Position = v;
}
