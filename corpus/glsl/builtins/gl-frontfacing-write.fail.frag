// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.2: "The fragment shader has access to the read-only built-in variable gl_FrontFacing"
#version 110
void main()
{
    gl_FrontFacing = true;
    gl_FragColor = vec4(1.0);
}
