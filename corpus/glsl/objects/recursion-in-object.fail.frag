// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 6.1: "Recursion is not allowed, not even statically." (drivers reject it when compiling the shader object)
float f(float x) { return x > 0.0 ? f(x - 1.0) : 0.0; }
