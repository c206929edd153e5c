// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.6: "indices used to subscript gl_TexCoord must either be an integral constant expressions, or this array must be re-declared by the shader with a size. The size can be at most gl_MaxTextureCoords."
#version 110
varying vec4 gl_TexCoord[2];
uniform int unit;
void main()
{
    gl_FragColor = gl_TexCoord[unit];
}
