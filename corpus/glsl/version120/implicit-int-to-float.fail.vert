// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 4.1.10: "There are no implicit conversions between types." (the same shader without #version 120)
#version 110
void main()
{
    float x = 1;
    gl_Position = vec4(x);
}
