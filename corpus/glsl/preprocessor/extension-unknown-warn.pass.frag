// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "warn ... Warn on the #extension if the extension extension_name is not supported."
#extension GL_ARBITER_no_such_extension : warn
void main()
{
    gl_FragColor = vec4(0.0);
}
