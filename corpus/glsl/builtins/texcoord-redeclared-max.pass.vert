// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.6: "The size can be at most gl_MaxTextureCoords."
varying vec4 gl_TexCoord[gl_MaxTextureCoords];
uniform int unit;
void main()
{
    gl_Position = ftransform();
    gl_TexCoord[unit] = gl_MultiTexCoord0;
}
