// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: gl_FragDepth is one of "The built-in variables that are accessible from a fragment shader"
#version 110
void main()
{
    gl_Position = vec4(0.0);
    gl_FragDepth = 0.5;
}
