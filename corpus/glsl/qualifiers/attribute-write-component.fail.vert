// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.4 "Attribute variables are read-only as far as the vertex shader is concerned."
attribute vec4 position;
void main()
{
    position.w = 1.0;
    gl_Position = position;
}
