// [config]
// expect_result: pass
// glsl_version: 1.20
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// ARB_texture_rectangle: "the compiler behaves as if #extension GL_ARB_texture_rectangle : require" is present, where the extension is supported
#version 120
uniform sampler2DRect image;
uniform sampler2DRectShadow depth;
void main()
{
    gl_FragColor = texture2DRect(image, gl_FragCoord.xy) * shadow2DRect(depth, vec3(gl_FragCoord.xy, 0.5));
}
