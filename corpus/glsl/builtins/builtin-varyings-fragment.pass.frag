// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.6: "The following varying variables are available to read from in a fragment shader. varying vec4 gl_Color; varying vec4 gl_SecondaryColor; varying vec4 gl_TexCoord[]; varying float gl_FogFragCoord;"
void main()
{
    gl_FragColor = gl_Color + gl_SecondaryColor + gl_TexCoord[0] * gl_FogFragCoord;
}
