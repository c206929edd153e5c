// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "If an array is indexed with an expression that is not an integral constant expression or passed as an argument to a function, then its size must be declared before any such use."
#version 110
uniform int index;
float values[];
void main()
{
    values[index] = 1.0;
    gl_Position = vec4(0.0);
}
