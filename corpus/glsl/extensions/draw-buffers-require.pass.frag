// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_draw_buffers
// [end config]
// ARB_draw_buffers: "#extension GL_ARB_draw_buffers : require" (gl_FragData and gl_MaxDrawBuffers are core in 1.10)
#extension GL_ARB_draw_buffers : require
void main()
{
    gl_FragData[0] = vec4(1.0);
    gl_FragData[1] = vec4(0.0);
}
