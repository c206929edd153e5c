// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "texture1DProj (sampler1D sampler, vec2 coord [, float bias] )" and "texture1DProj (sampler1D sampler, vec4 coord [, float bias] )" (no vec3 form)
uniform sampler1D s;
void main()
{
    gl_FragColor = texture1DProj(s, gl_TexCoord[0].xyz);
}
