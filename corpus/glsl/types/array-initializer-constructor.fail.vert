// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "There is no mechanism for initializing arrays at declaration time from within a shader."
#version 110
void main()
{
    float a[2] = float[2](1.0, 2.0);
    gl_Position = vec4(a[0]);
}
