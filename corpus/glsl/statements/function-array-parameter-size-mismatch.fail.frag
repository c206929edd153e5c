// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "the size of the array argument passed in must match the size specified in the formal parameter declaration."
#version 110
float sum(float a[2])
{
    return a[0] + a[1];
}
void main()
{
    float v[3];
    v[0] = 1.0; v[1] = 2.0; v[2] = 3.0;
    gl_FragColor = vec4(sum(v));
}
