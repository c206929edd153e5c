// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 4.3.5 "The uniform qualifier can be used with any of the basic data types, or when declaring a variable whose type is a structure, or an array of any of these."
// 4.1.9 "Variables of the same type can be aggregated into arrays by declaring a name followed by brackets ( [ ] ) enclosing an optional size."
#version 110
uniform vec4 colors[];
void main()
{
    gl_Position = colors[0] + colors[3];
}
