// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_fragment_coord_conventions
// [end config]
// 3.3: GL_ARB_fragment_coord_conventions is defined where the extension is supported; the redeclaration in the group compiled, the invalid one in the group skipped
#ifdef GL_ARB_fragment_coord_conventions
#extension GL_ARB_fragment_coord_conventions : enable
layout(pixel_center_integer) in vec4 gl_FragCoord;
#else
layout(pixel_center_integer, bogus) in vec3 gl_FragCoord;
#endif
void main()
{
    gl_FragColor = gl_FragCoord;
}
