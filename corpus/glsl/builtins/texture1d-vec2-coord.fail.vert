// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 texture1D (sampler1D sampler, float coord [, float bias] )"
uniform sampler1D s;
void main()
{
    gl_Position = texture1D(s, gl_MultiTexCoord0.xy);
}
