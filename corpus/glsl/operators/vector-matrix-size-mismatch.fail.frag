// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 5.10: "They require the size of the operands match."
#version 110
uniform mat4 m;
uniform vec2 v;
void main()
{
    vec2 r = v * m;
    gl_FragColor = vec4(r, 0.0, 1.0);
}
