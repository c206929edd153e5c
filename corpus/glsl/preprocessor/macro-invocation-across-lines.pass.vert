// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: the arguments of a macro invocation may span lines)
// 3.3 "Preprocessing does not change the number or relative location of new-lines in a source string."
#version 110
#define SQR(x) ((x) * (x))
void main()
{
    float v = SQR(
        2.0
    );
#if __LINE__ != 14
#error new-lines inside the macro invocation were not kept
#endif
    gl_Position = vec4(v);
}
