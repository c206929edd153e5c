// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.6: "varying vec4 gl_FrontColor; varying vec4 gl_BackColor; varying vec4 gl_FrontSecondaryColor; varying vec4 gl_BackSecondaryColor; varying vec4 gl_TexCoord[]; varying float gl_FogFragCoord;"
#version 110
void main()
{
    gl_Position = ftransform();
    gl_FrontColor = gl_Color;
    gl_BackColor = gl_Color.bgra;
    gl_FrontSecondaryColor = gl_SecondaryColor;
    gl_BackSecondaryColor = vec4(0.0);
    gl_TexCoord[0] = gl_MultiTexCoord0;
    gl_TexCoord[1] = gl_MultiTexCoord1;
    gl_FogFragCoord = gl_FogCoord;
}
