// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3: "genType step (genType edge, genType x)" and "genType step (float edge, genType x)" (there is no step(vec, float))
#version 110
uniform vec2 e;
uniform float x;
void main()
{
    gl_Position = vec4(step(e, x), 0.0, 1.0);
}
