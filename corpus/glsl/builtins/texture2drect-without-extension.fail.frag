// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: the 1.10 texture functions are the 1D, 2D, 3D, Cube and Shadow ones; texture2DRect and sampler2DRect exist only with GL_ARB_texture_rectangle (3.3: "#extension"), and sampler2DRect is reserved (3.6)
uniform sampler2DRect s;
void main()
{
    gl_FragColor = texture2DRect(s, gl_FragCoord.xy);
}
