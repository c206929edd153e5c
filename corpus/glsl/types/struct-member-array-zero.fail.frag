// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators can contain arrays. Such arrays must have a size specified, and the size must be an integral constant expression that's greater than zero"
struct S {
    float weights[0];
};
void main()
{
    gl_FragColor = vec4(0.0);
}
