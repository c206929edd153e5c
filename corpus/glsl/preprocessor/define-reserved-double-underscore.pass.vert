// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Accepted with the warning glsl-reserved-identifier: the name is reserved, and every driver
// (Mesa, glslang) accepts it (docs/glsl-disagreements.md).
// 3.3 "All macro names containing two consecutive underscores ( __ ) are reserved for future use as predefined macro names. All macro names prefixed with \"GL_\" ... are also reserved."
#version 110
#define MY__SCALE 2.0
void main()
{
    gl_Position = vec4(MY__SCALE);
}
