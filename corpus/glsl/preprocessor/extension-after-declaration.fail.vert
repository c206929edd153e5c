// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "If nothing is said, the granularity is a shader ... and the extension directives must occur before any non-preprocessor tokens."
#version 110
uniform float u;
#extension all : disable
void main()
{
    gl_Position = vec4(u);
}
