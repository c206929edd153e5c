// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.3: "attribute vec3 gl_Normal;"
#version 110
void main()
{
    vec4 n = gl_Normal;
    gl_Position = n;
}
