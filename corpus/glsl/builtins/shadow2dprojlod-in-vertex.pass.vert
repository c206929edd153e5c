// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 shadow2DProjLod(sampler2DShadow sampler, vec4 coord, float lod)"; "The built-ins suffixed with "Lod" are allowed only in a vertex shader."
uniform sampler2DShadow s;
void main()
{
    gl_Position = shadow2DProjLod(s, gl_MultiTexCoord0, 0.0);
}
