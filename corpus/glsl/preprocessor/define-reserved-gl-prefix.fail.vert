// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "All macro names containing two consecutive underscores ( __ ) are reserved for future use as predefined macro names. All macro names prefixed with \"GL_\" ... are also reserved."
#version 110
#define GL_MY_FEATURE 1
void main()
{
    gl_Position = vec4(0.0);
}
