// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9: an array size must be an integral constant expression; 4.3.3: one "that evaluates to a scalar integer" (1.20), here a vector
uniform vec4 a[ivec2(2, 2)];
void main()
{
    gl_Position = a[0];
}
