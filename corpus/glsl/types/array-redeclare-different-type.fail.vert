// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.9 "It is legal to declare an array without a size and then later re-declare the same name as an array of the same type and specify a size." ("as an array of the same type")
#version 110
float values[];
int values[3];
void main()
{
    gl_Position = vec4(0.0);
}
