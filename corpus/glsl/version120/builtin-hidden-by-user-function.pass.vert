// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.2: the user exp hides the built-in ones; calls of its own signature resolve to it
#version 120
float exp(float x, float y) { return x + y; }
void main()
{
    gl_Position = vec4(exp(2.0, 1.0));
}
