// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_draw_buffers
// [end config]
// 3.3: "each extension ... has a macro ... defined" (GL_ARB_draw_buffers is 1 where the extension is supported)
#if !defined(GL_ARB_draw_buffers) || GL_ARB_draw_buffers != 1
#error GL_ARB_draw_buffers must be defined as 1
#endif
void main()
{
    gl_FragData[0] = vec4(1.0);
}
