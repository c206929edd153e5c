// [config]
// expect_result: fail
// glsl_version: 1.20
// check_link: true
// [end config]
// 6.1: "if a function is called it must be defined" in the program (judged as a program: check_link)
#version 120
vec4 skin(vec4 position);
void main()
{
    gl_Position = gl_ModelViewProjectionMatrix * skin(gl_Vertex);
}
