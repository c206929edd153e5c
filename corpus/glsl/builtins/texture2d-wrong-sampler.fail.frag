// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 texture2D (sampler2D sampler, vec2 coord [, float bias] )"
uniform sampler3D s;
void main()
{
    gl_FragColor = texture2D(s, gl_TexCoord[0].xy);
}
