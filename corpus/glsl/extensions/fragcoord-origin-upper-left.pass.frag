// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "layout(origin_upper_left) in vec4 gl_FragCoord;" is an allowed redeclaration; GLSL 1.10 with the extension enabled (what arbiter translate emits for OPTION ARB_fragment_coord_origin_upper_left)
#version 110
#extension GL_ARB_fragment_coord_conventions : require
layout(origin_upper_left) in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = gl_FragCoord;
}
