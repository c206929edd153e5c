// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "All macro names containing two consecutive underscores ( __ ) are reserved for future use as predefined macro names. All macro names prefixed with \"GL_\" ... are also reserved."
// 3.3 "#define and #undef functionality are defined as is standard for C++ preprocessors for macro definitions both with and without macro parameters." (C++: a predefined macro name shall not be defined or undefined)
#version 110
#define __VERSION__ 120
void main()
{
    gl_Position = vec4(0.0);
}
