// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Global variables can only use the qualifiers const, attribute, uniform, or varying. Only one may be specified."
#version 110
const const float c = 1.0;
void main()
{
    gl_Position = vec4(0.0);
}
