// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "__LINE__ will substitute a decimal integer constant that is one more than the number of preceding new-lines in the current source string." (expanded where the macro is used)
#define HERE __LINE__

#if HERE != 8
#error HERE is wrong
#endif
void main()
{
    gl_Position = vec4(0.0);
}
