// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is also illegal to index an array with a negative constant expression."
#version 110
void main()
{
    float a[3];
    a[-1] = 1.0;
    gl_Position = vec4(0.0);
}
