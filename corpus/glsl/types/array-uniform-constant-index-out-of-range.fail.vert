// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is illegal to declare an array with a size, and then later (in the same shader) index the same array with an integral constant expression greater than or equal to the declared size."
#version 110
uniform vec4 colors[2];
void main()
{
    gl_Position = colors[2];
}
