// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.4: "The following built-in constants are provided to vertex and fragment shaders."
void main()
{
    gl_FragColor = vec4(float(gl_MaxDrawBuffers), float(gl_MaxTextureImageUnits),
                        float(gl_MaxLights), float(gl_MaxVertexAttribs));
}
