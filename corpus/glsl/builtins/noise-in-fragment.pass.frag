// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.9: "Noise functions are available to both fragment and vertex shaders."
#version 110
void main()
{
    gl_FragColor = noise4(gl_TexCoord[0].xyz) + vec4(noise3(gl_FragCoord.x), 1.0);
}
