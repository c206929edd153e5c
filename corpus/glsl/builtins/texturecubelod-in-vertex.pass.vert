// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 textureCubeLod (samplerCube sampler, vec3 coord, float lod)"; "The built-ins suffixed with "Lod" are allowed only in a vertex shader."
#version 110
uniform samplerCube s;
void main()
{
    gl_Position = textureCubeLod(s, gl_Normal, 1.0);
}
