// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "__FILE__ will substitute a decimal integer constant that says which source string number is currently being processed." ("the first string being string 0")
#version 110
#if __FILE__ != 0
#error __FILE__ is not 0
#endif
void main()
{
    gl_Position = vec4(float(__FILE__));
}
