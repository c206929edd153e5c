// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.6 "A vertex shader may also read varying variables, getting back the same values it has written."
#version 110
varying vec4 color;
void main()
{
    color = vec4(0.5);
    color.a = color.r * 2.0;
    gl_Position = color;
}
