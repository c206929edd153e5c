// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 4.6.1: "invariant gl_Position;" and "invariant varying vec3 Color;"; 4.3.6: "centroid varying"
#version 120
invariant gl_Position;
invariant varying vec3 color;
centroid varying vec2 uv;
void main()
{
    color = gl_Color.rgb;
    uv = gl_MultiTexCoord0.xy;
    gl_Position = ftransform();
}
