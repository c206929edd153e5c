// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Function return types and structure fields do not use qualifiers."
#version 110
varying vec4 color()
{
    return vec4(1.0);
}
void main()
{
    gl_Position = color();
}
