// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.3 "Any number greater than the latest version of the language a compiler supports will also cause an error to be generated."
#version 999
void main()
{
    gl_Position = vec4(0.0);
}
