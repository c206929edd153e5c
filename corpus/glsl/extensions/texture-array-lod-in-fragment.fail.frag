// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_EXT_texture_array
// [end config]
// EXT_texture_array 8.7: the Lod array functions, as the 1.10 Lod functions, "are only available in a vertex shader"
#extension GL_EXT_texture_array : require
uniform sampler2DArray layers;
void main()
{
    gl_FragColor = texture2DArrayLod(layers, vec3(0.0), 1.0);
}
