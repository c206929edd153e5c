// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4 "There are no default types. All variable and function declarations must have a declared type"
// 4.1.1 "Functions that do not return a value must be declared as void. There is no default function return type."
#version 110
helper()
{
}
void main()
{
    gl_Position = vec4(0.0);
}
