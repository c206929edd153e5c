// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x: "Declarations of layouts can only be made at global scope"
#version 110
#extension GL_ARB_fragment_coord_conventions : require
void main()
{
    layout(origin_upper_left) in vec4 gl_FragCoord;
    gl_FragColor = gl_FragCoord;
}
