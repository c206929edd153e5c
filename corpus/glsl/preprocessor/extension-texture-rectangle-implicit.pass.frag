// [config]
// expect_result: pass
// glsl_version: 1.10
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// ARB_texture_rectangle makes the extension implicitly enabled where it is supported (the
// default profile); under --limits spec-min this shader is rejected.
// 3.3 "The initial state of the compiler is as if the directive #extension all : disable was issued"
// 3.6 "sampler2DRect" is a keyword reserved for future use
#version 110
uniform sampler2DRect tex;
void main()
{
    gl_FragColor = texture2DRect(tex, gl_FragCoord.xy);
}
