// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 shadow1D (sampler1DShadow sampler, vec3 coord [, float bias] )"
#version 110
uniform sampler2DShadow s;
void main()
{
    gl_FragColor = shadow1D(s, gl_TexCoord[0].xyz);
}
