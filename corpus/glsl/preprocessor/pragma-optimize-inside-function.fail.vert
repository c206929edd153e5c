// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "#pragma optimize(on) / #pragma optimize(off) ... It can only be used outside function definitions." (same for debug)
#version 110
void main()
{
#pragma optimize(off)
    gl_Position = vec4(0.0);
}
