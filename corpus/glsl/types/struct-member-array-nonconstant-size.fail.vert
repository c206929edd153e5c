// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators can contain arrays. Such arrays must have a size specified, and the size must be an integral constant expression that's greater than zero"
#version 110
uniform int n;
struct S {
    float weights[n];
};
void main()
{
    gl_Position = vec4(0.0);
}
