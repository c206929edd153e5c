// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 texture2DLod (sampler2D sampler, vec2 coord, float lod)"; 6.1: "No promotion or demotion of the return type or input argument types is done."
#version 110
uniform sampler2D s;
void main()
{
    gl_Position = texture2DLod(s, gl_MultiTexCoord0.xy, 0);
}
