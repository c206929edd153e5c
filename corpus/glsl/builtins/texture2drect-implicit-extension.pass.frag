// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// ARB_texture_rectangle: "the compiler behaves as if #extension GL_ARB_texture_rectangle : require"
// were present where the implementation supports the extension (the default profile, Mesa's,
// does; --limits spec-min does not, and rejects this shader).
// Section 8.7: the 1.10 texture functions are the 1D, 2D, 3D, Cube and Shadow ones; texture2DRect and sampler2DRect exist only with GL_ARB_texture_rectangle (3.3: "#extension"), and sampler2DRect is reserved (3.6)
uniform sampler2DRect s;
void main()
{
    gl_FragColor = texture2DRect(s, gl_FragCoord.xy);
}
