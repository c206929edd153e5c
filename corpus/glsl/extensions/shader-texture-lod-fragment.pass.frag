// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_shader_texture_lod
// [end config]
// ARB_shader_texture_lod: "If enabled by the preprocessor directive #extension, the \"Lod\" functions may also be used in a fragment shader"
#extension GL_ARB_shader_texture_lod : require
uniform sampler2D s;
void main()
{
    gl_FragColor = texture2DLod(s, vec2(0.5), 2.0) + texture2DGradARB(s, vec2(0.5), vec2(0.1), vec2(0.1));
}
