// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Expressions following #if and #elif are restricted to expressions operating on literal integer constants, plus identifiers consumed by the defined operator."
#version 110
#if 1.0
#endif
void main()
{
    gl_Position = vec4(0.0);
}
