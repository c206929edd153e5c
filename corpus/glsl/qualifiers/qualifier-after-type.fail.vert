// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.3 "Variable declarations may have one or more qualifiers, specified in front of the type."
#version 110
float const c = 1.0;
void main()
{
    gl_Position = vec4(0.0);
}
