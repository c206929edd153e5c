// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Accepted with the warning glsl-reserved-identifier: the name is reserved, and every driver
// (Mesa, glslang) accepts it (docs/glsl-disagreements.md).
// 3.3 "All macro names containing two consecutive underscores ( __ ) are reserved for future use as predefined macro names. All macro names prefixed with \"GL_\" ... are also reserved."
#define __MY_SCALE 2.0
void main()
{
    gl_FragColor = vec4(__MY_SCALE);
}
