// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3 "Global variables can only use the qualifiers const, attribute, uniform, or varying. Only one may be specified."
#version 110
const float c = 1.0;
attribute vec4 position;
uniform mat4 mvp;
varying vec4 color;
float plain = 2.0;
void main()
{
    color = vec4(c * plain);
    gl_Position = mvp * position;
}
