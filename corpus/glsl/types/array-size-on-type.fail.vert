// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "Variables of the same type can be aggregated into arrays by declaring a name followed by brackets ( [ ] ) enclosing an optional size." ("declaring a name followed by brackets")
#version 110
void main()
{
    float[3] a;
    gl_Position = vec4(0.0);
}
