// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 5.7, 5.8: arrays are first class (whole arrays are l-values): an array may be an out parameter
#version 120
void fill(out float weights[3]) { weights = float[3](1.0, 0.0, 0.0); }
void main()
{
    float w[3];
    fill(w);
    gl_Position = vec4(w[0]);
}
