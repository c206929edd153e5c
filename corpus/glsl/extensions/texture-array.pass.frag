// [config]
// expect_result: pass
// glsl_version: 1.20
// require_extensions: GL_EXT_texture_array
// [end config]
// EXT_texture_array: "vec4 texture2DArray(sampler2DArray sampler, vec3 coord [, float bias])" and "vec4 shadow2DArray(sampler2DArrayShadow sampler, vec4 coord)"
#version 120
#extension GL_EXT_texture_array : require
uniform sampler2DArray layers;
uniform sampler2DArrayShadow shadows;
void main()
{
    gl_FragColor = texture2DArray(layers, vec3(gl_TexCoord[0].xy, 2.0), 0.5)
                 * shadow2DArray(shadows, vec4(gl_TexCoord[0].xy, 1.0, 0.5));
}
