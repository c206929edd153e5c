// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.1: "genType atan (genType y, genType x)" (both arguments have the same genType)
#version 110
uniform vec2 y;
uniform float x;
void main()
{
    gl_FragColor = vec4(atan(y, x), 0.0, 1.0);
}
