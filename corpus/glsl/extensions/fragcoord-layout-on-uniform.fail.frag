// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "Fragment shaders can have an input layout only for redeclaring the built-in variable gl_FragCoord"
#version 110
#extension GL_ARB_fragment_coord_conventions : require
layout(origin_upper_left) uniform vec4 position;
void main()
{
    gl_FragColor = position;
}
