// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 5.8: "non-dereferenced arrays ... cannot be l-values": an array cannot be an out or inout parameter
#version 110
void fill(out float weights[3]) { weights[0] = 1.0; weights[1] = 0.0; weights[2] = 0.0; }
void main()
{
    float w[3];
    fill(w);
    gl_Position = vec4(w[0]);
}
