// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: gl_FrontColor is among "The following built-in varying variables are available to write to in a vertex shader"; the fragment shader has gl_Color instead
#version 110
void main()
{
    gl_FragColor = gl_FrontColor;
}
