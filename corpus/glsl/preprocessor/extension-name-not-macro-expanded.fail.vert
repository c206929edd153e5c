// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// 3.3 "Macro expansion is not done on lines containing #extension and #version directives."
// 3.3 "require ... Give an error on the #extension if the extension extension_name is not supported, or if all is specified."
#version 110
#define RECT GL_ARB_texture_rectangle
#extension RECT : require
void main()
{
    gl_Position = vec4(0.0);
}
