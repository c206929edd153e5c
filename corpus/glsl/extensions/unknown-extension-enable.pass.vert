// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3: "enable: ... Warn on the #extension if the extension extension_name is not supported."
#extension GL_NV_no_such_extension : enable
void main()
{
    gl_Position = ftransform();
}
