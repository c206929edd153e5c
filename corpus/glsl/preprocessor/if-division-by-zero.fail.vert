// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "The semantics of applying operators to integer literals in the preprocessor match those standard in the C++ preprocessor" (C++: division by zero in #if is an error)
#version 110
#if 1 / 0
#endif
void main()
{
    gl_Position = vec4(0.0);
}
