// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.9: "one can be a scalar float and the other a float vector or matrix"
#version 110
uniform mat2 m;
void main()
{
    mat2 n = m * 2;
    gl_Position = vec4(n[0], n[1]);
}
