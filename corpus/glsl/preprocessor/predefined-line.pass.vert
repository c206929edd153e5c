// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "__LINE__ will substitute a decimal integer constant that is one more than the number of preceding new-lines in the current source string."
#version 110
#if __LINE__ != 7
#error __LINE__ is wrong
#endif
void main()
{
    gl_Position = vec4(float(__LINE__));
}
