// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "All redeclarations of gl_FragCoord in all fragment shaders in a single program must have the same set of qualifiers"
#version 110
#extension GL_ARB_fragment_coord_conventions : require
layout(origin_upper_left) in vec4 gl_FragCoord;
layout(origin_upper_left, pixel_center_integer) in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = gl_FragCoord;
}
