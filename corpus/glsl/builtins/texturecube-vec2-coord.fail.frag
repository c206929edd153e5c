// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "vec4 textureCube (samplerCube sampler, vec3 coord [, float bias] )"
#version 110
uniform samplerCube s;
void main()
{
    gl_FragColor = textureCube(s, gl_TexCoord[0].xy);
}
