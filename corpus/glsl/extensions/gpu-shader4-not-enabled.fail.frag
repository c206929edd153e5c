// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 5.x: "%" and the bitwise operators are reserved ("the operator modulus (%) is reserved for future use"); EXT_gpu_shader4 adds them only where enabled
#version 120
void main()
{
    int a = 7 % 2;
    gl_FragColor = vec4(float(a));
}
