// [config]
// expect_result: pass
// glsl_version: 1.20
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// ARB_fragment_coord_conventions 4.3.x.1: "layout(origin_upper_left, pixel_center_integer) in vec4 gl_FragCoord;"; 4.3.x: the identifiers "are not case-sensitive"
#version 120
#extension GL_ARB_fragment_coord_conventions : enable
layout(pixel_center_integer, ORIGIN_UPPER_LEFT) in vec4 gl_FragCoord;
void main()
{
    gl_FragColor = vec4(gl_FragCoord.xy, 0.0, 1.0);
}
