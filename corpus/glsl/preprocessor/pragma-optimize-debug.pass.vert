// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#pragma optimize(on) / #pragma optimize(off) ... #pragma debug(on) / #pragma debug(off)"
#version 110
#pragma optimize(on)
#pragma optimize(off)
#pragma debug(on)
#pragma debug(off)
void main()
{
    gl_Position = vec4(0.0);
}
