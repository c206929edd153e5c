// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 5.1: "selection ?: Right to Left" and "assignment = Right to Left"
#version 110
uniform bool p;
uniform bool q;
void main()
{
    float x;
    float y;
    x = y = p ? 1.0 : q ? 2.0 : 3.0;
    gl_Position = vec4(x, y, 0.0, 1.0);
}
