// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6: "a shader is a sequence of declarations and function bodies."
#version 110
uniform vec4 offset;
float scale(float x);
const float k = 2.0;
float scale(float x)
{
    return x * k;
}
void main()
{
    gl_Position = offset * scale(0.5);
}
