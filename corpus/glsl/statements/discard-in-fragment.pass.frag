// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 6.4: "The discard keyword is only allowed within fragment shaders." e.g. "if (intensity < 0.0) discard;"
#version 110
uniform float intensity;
void main()
{
    if (intensity < 0.0)
        discard;
    gl_FragColor = vec4(intensity);
}
