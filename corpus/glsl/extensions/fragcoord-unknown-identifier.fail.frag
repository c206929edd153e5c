// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "The layout qualifier identifiers for gl_FragCoord are origin_upper_left pixel_center_integer"
#version 110
#extension GL_ARB_fragment_coord_conventions : require
layout(origin_lower_left) in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = gl_FragCoord;
}
