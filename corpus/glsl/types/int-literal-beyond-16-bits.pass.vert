// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.1.3 "An implementation is allowed to use more than 16 bits of precision to manipulate integers. ... Shaders that overflow the 16 bits of precision may not be portable."
#version 110
void main()
{
    int a = 65536;
    int b = 2147483647;
    int c = 0x7FFFFFFF;
    int d = 017777777777;
    gl_Position = vec4(float(a), float(b), float(c), float(d));
}
