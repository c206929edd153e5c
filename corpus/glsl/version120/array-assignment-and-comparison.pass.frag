// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 5.7: arrays are first class: "array assignment" and the equality operators apply to whole arrays (5.8, 5.9)
#version 120
uniform float u[2];
void main()
{
    float a[2];
    a = u;
    gl_FragColor = vec4(a == u ? 1.0 : 0.0);
}
