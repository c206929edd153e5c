// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// 3.3 "Directives that occur later override those seen earlier. The all variant sets the behavior for all extensions, overriding all previously issued extension directives, but only for the behaviors warn and disable."
#extension GL_ARB_texture_rectangle : enable
#extension GL_ARB_texture_rectangle : disable
uniform sampler2DRect tex;
void main()
{
    gl_FragColor = texture2DRect(tex, gl_FragCoord.xy);
}
