// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "If an implementation does not recognize the tokens following #pragma, then it will ignore that pragma."
#version 110
void main()
{
#pragma some_vendor_option(on)
    gl_Position = vec4(0.0);
}
