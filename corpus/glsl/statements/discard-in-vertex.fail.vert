// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.4: "The discard keyword is only allowed within fragment shaders."; 9: "DISCARD SEMICOLON // Fragment shader only."
#version 110
uniform float intensity;
void main()
{
    if (intensity < 0.0)
        discard;
    gl_Position = vec4(intensity);
}
