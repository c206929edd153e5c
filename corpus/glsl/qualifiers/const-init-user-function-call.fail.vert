// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3.2 "Constructors may be used in such expressions, but function calls may not."
#version 110
float one()
{
    return 1.0;
}
const float c = one();
void main()
{
    gl_Position = vec4(0.0);
}
