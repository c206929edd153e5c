// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1 "There are no pointer types."
#version 110
void main()
{
    float x = 1.0;
    float *p;
    gl_Position = vec4(x);
}
