// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.4 "Attribute variables are read-only as far as the vertex shader is concerned."
// 4.3.4 "Attribute variables are required to have global scope, and must be declared outside of function bodies, before their first use."
#version 110
attribute vec4 position;
vec4 transformed()
{
    return gl_ModelViewProjectionMatrix * position;
}
void main()
{
    gl_Position = transformed();
}
