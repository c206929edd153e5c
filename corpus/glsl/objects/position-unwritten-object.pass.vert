// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 7.1: gl_Position must be written by every execution of the vertex shader: a program property (a shader object may leave it to another; a warning when it has main())
void main()
{
    gl_FrontColor = gl_Color;
}
