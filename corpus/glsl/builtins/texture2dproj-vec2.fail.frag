// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "texture2DProj (sampler2D sampler, vec3 coord [, float bias] )" and "(sampler2D sampler, vec4 coord [, float bias] )"
#version 110
uniform sampler2D s;
void main()
{
    gl_FragColor = texture2DProj(s, gl_TexCoord[0].xy);
}
