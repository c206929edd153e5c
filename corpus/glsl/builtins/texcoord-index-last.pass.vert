// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.6: "varying vec4 gl_TexCoord[]; // at most will be gl_MaxTextureCoords" (the last element, gl_MaxTextureCoords - 1, may be written)
void main()
{
    gl_Position = ftransform();
    gl_TexCoord[gl_MaxTextureCoords - 1] = gl_MultiTexCoord0;
}
