// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 6.1: the function main "takes no arguments, returns no value, and must be declared as type void"
#version 110
void main(float x)
{
    gl_FragColor = vec4(x);
}
