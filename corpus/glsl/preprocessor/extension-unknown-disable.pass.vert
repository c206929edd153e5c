// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 3.3 "disable ... Warn on the #extension if the extension extension_name is not supported."
#version 110
#extension GL_ARBITER_no_such_extension : disable
void main()
{
    gl_Position = vec4(0.0);
}
