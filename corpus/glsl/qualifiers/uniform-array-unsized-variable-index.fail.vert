// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.5 "The uniform qualifier can be used with any of the basic data types, or when declaring a variable whose type is a structure, or an array of any of these."
// 4.1.9 "If an array is indexed with an expression that is not an integral constant expression or passed as an argument to a function, then its size must be declared before any such use."
#version 110
uniform vec4 colors[];
uniform int index;
void main()
{
    gl_Position = colors[index];
}
