// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "The built-in variables that are accessible from a fragment shader are intrinsically given types as follows: ... vec4 gl_FragColor;" (not accessible from a vertex shader)
#version 110
void main()
{
    gl_Position = vec4(0.0);
    gl_FragColor = vec4(1.0);
}
