// [config]
// expect_result: fail
// glsl_version: 1.20
// [end config]
// 3.3: "Any number greater than the latest version of the language a compiler supports will also cause an error to be generated." (arbiter checks 1.10 and 1.20)
#version 130
in vec4 position;
void main()
{
    gl_Position = position;
}
