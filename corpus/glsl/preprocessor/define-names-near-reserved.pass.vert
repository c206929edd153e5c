// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "All macro names containing two consecutive underscores ( __ ) are reserved for future use as predefined macro names. All macro names prefixed with \"GL_\" ... are also reserved." (only __ anywhere and a GL_ prefix are reserved)
#version 110
#define GL 1.0
#define GLX_SCALE 1.0
#define gl_scale 1.0
#define MY_GL_SCALE 1.0
#define _A 1.0
#define A_ 1.0
#define _ 1.0
void main()
{
    gl_Position = vec4(GL * GLX_SCALE * gl_scale * MY_GL_SCALE * _A * A_ * _);
}
