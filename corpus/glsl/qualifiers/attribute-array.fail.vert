// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.4 "Attribute variables cannot be declared as arrays or structures."
#version 110
attribute vec4 positions[2];
void main()
{
    gl_Position = vec4(0.0);
}
