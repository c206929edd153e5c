// [config]
// expect_result: fail
// glsl_version: 1.10
// require_extensions: GL_ARB_explicit_attrib_location
// [end config]
// GL_ARB_explicit_attrib_location gives layout(location) to vertex shader inputs declared with in; an attribute takes no layout qualifier (Mesa: "layout qualifier may not be used with attribute or varying")
#extension GL_ARB_explicit_attrib_location : require
layout(location = 1) attribute vec4 position;
void main()
{
    gl_Position = position;
}
