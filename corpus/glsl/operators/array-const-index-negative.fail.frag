// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 4.1.9 (used by 5.2): "It is also illegal to index an array with a negative constant expression."
#version 110
uniform vec4 w[2];
void main()
{
    gl_FragColor = w[-1];
}
