// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.3.3: "Function calls to user-defined functions (non-built-in functions) cannot be used to form constant expressions."
#version 120
float twice(float x) { return 2.0 * x; }
const float k = twice(1.0);
void main()
{
    gl_Position = vec4(k);
}
