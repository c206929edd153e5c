// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.4 "It is an error to declare an attribute variable in any type of shader other than a vertex shader."
attribute vec4 color;
void main()
{
    gl_FragColor = color;
}
