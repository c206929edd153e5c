// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.2 "The right side of the assignment operator ( = ) can be any expression whose type is bool."
// 4.1.2 "bool success; // declare \"success\" to be a Boolean / bool done = false;"
#version 110
uniform float a;
void main()
{
    bool success;
    bool done = false;
    bool less = a < 1.0;
    success = !done && less;
    gl_Position = vec4(success ? 1.0 : 0.0);
}
