// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// 3.3 and ARB_fragment_coord_conventions: the layout qualifier is the extension's, and the shader does not enable it (disable after enable)
#version 110
#extension GL_ARB_fragment_coord_conventions : enable
#extension GL_ARB_fragment_coord_conventions : disable
layout(origin_upper_left) in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = gl_FragCoord;
}
