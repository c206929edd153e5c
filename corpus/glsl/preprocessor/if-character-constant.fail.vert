// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Character constants are not supported."
#version 110
#if 'a' == 97
#endif
void main()
{
    gl_Position = vec4(0.0);
}
