// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.3: "attribute vec4 gl_Color; ... attribute vec3 gl_Normal; attribute vec4 gl_Vertex; attribute vec4 gl_MultiTexCoord0; ... attribute vec4 gl_MultiTexCoord7; attribute float gl_FogCoord;"
void main()
{
    vec4 t = gl_MultiTexCoord0 + gl_MultiTexCoord1 + gl_MultiTexCoord2 + gl_MultiTexCoord3
           + gl_MultiTexCoord4 + gl_MultiTexCoord5 + gl_MultiTexCoord6 + gl_MultiTexCoord7;
    vec3 n = gl_Normal;
    float f = gl_FogCoord;
    gl_Position = gl_Vertex + gl_Color + gl_SecondaryColor + t + vec4(n, f);
}
