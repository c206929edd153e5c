// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 1.20 4.2: "All variable names, structure type names, and function names in a given scope share the same name space." (a const variable redeclares a function's name)
#version 120
float scale(float x)
{
    return x * 2.0;
}
const float scale = 2.0;
void main()
{
    gl_Position = vec4(scale);
}
