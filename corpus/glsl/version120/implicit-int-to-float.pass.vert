// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.1.10: "There are no implicit conversions between types ... except for integer to float in some contexts"; 1.2: "Automatically convert integer types to float types, as needed by context."
#version 120
void main()
{
    float x = 1;
    vec2 v = vec2(2, 3) * 2;
    gl_Position = vec4(x + v.x, v.y, 0, 1);
}
