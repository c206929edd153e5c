// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3: "require: Behave as specified by the extension extension_name. Give an error on the #extension if the extension extension_name is not supported"
#extension GL_NV_no_such_extension : require
void main()
{
    gl_Position = ftransform();
}
