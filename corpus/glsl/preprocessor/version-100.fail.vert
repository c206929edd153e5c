// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Any number less than 110 will cause an error to be generated."
#version 100
void main()
{
    gl_Position = vec4(0.0);
}
