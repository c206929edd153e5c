// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 texture2DLod (sampler2D sampler, vec2 coord, float lod)"; "The built-ins suffixed with "Lod" are allowed only in a vertex shader."
uniform sampler2D s;
void main()
{
    gl_Position = texture2DLod(s, gl_MultiTexCoord0.xy, 0.0);
}
