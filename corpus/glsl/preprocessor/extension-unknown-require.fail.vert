// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "require ... Give an error on the #extension if the extension extension_name is not supported, or if all is specified."
#version 110
#extension GL_ARBITER_no_such_extension : require
void main()
{
    gl_Position = vec4(0.0);
}
