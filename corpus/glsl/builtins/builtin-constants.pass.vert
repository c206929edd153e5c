// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.4: "The following built-in constants are provided to vertex and fragment shaders. const int gl_MaxLights = 8; ..." (integral constant expressions usable as array sizes, 4.3.3)
#version 110
uniform vec4 lights[gl_MaxLights];
float planes[gl_MaxClipPlanes];
void main()
{
    int total = gl_MaxTextureUnits + gl_MaxTextureCoords + gl_MaxVertexAttribs
              + gl_MaxVertexUniformComponents + gl_MaxVaryingFloats
              + gl_MaxVertexTextureImageUnits + gl_MaxCombinedTextureImageUnits
              + gl_MaxTextureImageUnits + gl_MaxFragmentUniformComponents + gl_MaxDrawBuffers;
    planes[0] = float(total);
    gl_Position = lights[gl_MaxLights - 1] * planes[0];
}
