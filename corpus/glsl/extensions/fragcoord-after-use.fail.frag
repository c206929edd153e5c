// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "Within any shader, the first redeclarations of gl_FragCoord must appear before any use of gl_FragCoord" (a use through a macro)
#version 110
#extension GL_ARB_fragment_coord_conventions : require
#define WINDOW_XY gl_FragCoord.xy
vec2 window() { return WINDOW_XY; }
layout(origin_upper_left) in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = vec4(window(), 0.0, 1.0);
}
