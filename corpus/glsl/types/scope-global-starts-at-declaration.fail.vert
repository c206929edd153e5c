// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "If it is declared outside all function definitions, it has global scope, which starts from where it is declared and persists to the end of the shader it is declared in."
#version 110
float get()
{
    return g;
}
float g = 2.0;
void main()
{
    gl_Position = vec4(get());
}
