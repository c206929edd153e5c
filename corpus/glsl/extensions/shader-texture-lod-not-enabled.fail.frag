// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 8.7: the "Lod" functions "are only available in a vertex shader"; ARB_shader_texture_lod makes them available to fragment shaders only "if enabled by the preprocessor directive #extension"
uniform sampler2D s;
void main()
{
    gl_FragColor = texture2DLod(s, vec2(0.5), 2.0);
}
