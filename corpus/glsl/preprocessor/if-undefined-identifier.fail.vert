// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Expressions following #if and #elif are restricted to expressions operating on literal integer constants, plus identifiers consumed by the defined operator." (an identifier that is not a macro and not the operand of defined is not allowed)
#version 110
#if UNDEFINED_NAME
#endif
void main()
{
    gl_Position = vec4(0.0);
}
