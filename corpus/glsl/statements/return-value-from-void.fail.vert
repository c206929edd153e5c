// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: "Functions that return no value must be declared as void."; 6.4: "return expression" supplies "the return value for the function"
#version 110
void f()
{
    return 1.0;
}
void main()
{
    f();
    gl_Position = vec4(1.0);
}
