// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "When an array size is specified in a declaration, it must be an integral constant expression (see Section 4.3.3) greater than zero."
#version 110
void main()
{
    float a[0];
    gl_Position = vec4(0.0);
}
