// [config]
// expect_result: pass
// glsl_version: 1.20
// [end config]
// 1.20 7.2: "varying vec2 gl_PointCoord;" (fragment shaders)
#version 120
uniform sampler2D sprite;
void main()
{
    gl_FragColor = texture2D(sprite, gl_PointCoord);
}
