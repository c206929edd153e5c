// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "texture2D (sampler2D sampler, vec2 coord [, float bias] )"; 6.1: "No promotion or demotion of the return type or input argument types is done."
uniform sampler2D s;
void main()
{
    gl_FragColor = texture2D(s, gl_TexCoord[0].xy, 1);
}
