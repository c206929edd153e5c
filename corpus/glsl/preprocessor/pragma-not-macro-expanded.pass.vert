// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "Tokens following #pragma are not subject to preprocessor macro expansion."
#version 110
#define optimize(x) garbage
#pragma optimize(off)
void main()
{
    gl_Position = vec4(0.0);
}
