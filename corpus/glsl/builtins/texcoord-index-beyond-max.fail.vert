// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: "varying vec4 gl_TexCoord[]; // at most will be gl_MaxTextureCoords" and "The size can be at most gl_MaxTextureCoords."
void main()
{
    gl_Position = ftransform();
    gl_TexCoord[gl_MaxTextureCoords] = gl_MultiTexCoord0;
}
