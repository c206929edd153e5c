// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 5.4: constructors are for vectors, matrices and structures only; 1.10 has no array constructors
#version 110
void main()
{
    float a[2] = float[2](1.0, 2.0);
    gl_Position = vec4(a[0]);
}
