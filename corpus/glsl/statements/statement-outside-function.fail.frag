// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6: "a shader is a sequence of declarations and function bodies"; an expression statement is not a global-declaration
#version 110
float x;
x = 1.0;
void main()
{
    gl_FragColor = vec4(x);
}
