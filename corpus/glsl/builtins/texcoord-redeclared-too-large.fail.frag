// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: "this array must be re-declared by the shader with a size. The size can be at most gl_MaxTextureCoords."
#version 110
varying vec4 gl_TexCoord[gl_MaxTextureCoords + 1];
void main()
{
    gl_FragColor = gl_TexCoord[0];
}
