// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// 3.3 "require ... Give an error on the #extension if the extension extension_name is not supported, or if all is specified."
// 3.3 "require: Behave as specified by the extension extension_name."
#version 110
#extension GL_ARB_texture_rectangle : require
uniform sampler2DRect tex;
void main()
{
    gl_FragColor = texture2DRect(tex, gl_FragCoord.xy);
}
