// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "Vertex shaders do not have any input layout qualifiers"; gl_FragCoord "is only predeclared in fragment shaders, so redeclaring it in any other shader language will be illegal"
#version 110
#extension GL_ARB_fragment_coord_conventions : require
layout(origin_upper_left) in vec4 gl_FragCoord;
void main()
{
    gl_Position = vec4(0.0);
}
