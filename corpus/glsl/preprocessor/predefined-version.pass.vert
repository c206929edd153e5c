// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "__VERSION__ will substitute a decimal integer reflecting the version number ... __VERSION__ substitute the decimal integer 110."
#version 110
#if __VERSION__ != 110
#error __VERSION__ is not 110
#endif
void main()
{
    int v = __VERSION__;
    gl_Position = vec4(float(v));
}
