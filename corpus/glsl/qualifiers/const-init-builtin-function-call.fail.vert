// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Constructors may be used in such expressions, but function calls may not."
#version 110
const float c = sin(0.0);
void main()
{
    gl_Position = vec4(c);
}
