// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.3 lists the common functions of 1.10; trunc (GLSL 1.30) is not among them
#version 110
uniform float f;
void main()
{
    gl_Position = vec4(trunc(f));
}
