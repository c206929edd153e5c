// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// Section 3.3: "#extension extension_name : require" enables the extension (GL_ARB_texture_rectangle adds sampler2DRect and texture2DRect); 8.7 texture lookup rules otherwise apply
#version 110
#extension GL_ARB_texture_rectangle : require
uniform sampler2DRect s;
void main()
{
    gl_FragColor = texture2DRect(s, gl_FragCoord.xy);
}
