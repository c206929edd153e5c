// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_texture_rectangle
// [end config]
// ARB_texture_rectangle: "vec4 texture2DRect(sampler2DRect sampler, vec2 coord)" (a vec3 coordinate matches no overload)
#extension GL_ARB_texture_rectangle : require
uniform sampler2DRect image;
void main()
{
    gl_FragColor = texture2DRect(image, vec3(0.0));
}
