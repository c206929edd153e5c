// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "There are no default types. All variable and function declarations must have a declared type"
#version 110
const x = 1.0;
void main()
{
    gl_Position = vec4(0.0);
}
