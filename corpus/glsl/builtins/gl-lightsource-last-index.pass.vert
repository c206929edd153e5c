// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 7.5: "uniform gl_LightSourceParameters gl_LightSource[gl_MaxLights];"
#version 110
void main()
{
    gl_Position = ftransform() + gl_LightSource[gl_MaxLights - 1].position + gl_ClipPlane[gl_MaxClipPlanes - 1];
}
