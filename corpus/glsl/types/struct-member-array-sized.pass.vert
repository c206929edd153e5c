// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.8 "Member declarators can contain arrays. Such arrays must have a size specified, and the size must be an integral constant expression that's greater than zero"
#version 110
const int N = 2;
struct S {
    float weights[4];
    vec2 points[N];
    vec3 more[N * 2 + 1];
};
void main()
{
    S s;
    s.weights[3] = 1.0;
    s.points[1] = vec2(s.weights[3]);
    s.more[4] = vec3(s.points[1], 1.0);
    gl_Position = vec4(s.more[4], 1.0);
}
