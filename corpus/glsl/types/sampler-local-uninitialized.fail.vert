// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "They can only be declared as function parameters or uniforms"
#version 110
void main()
{
    sampler2D local;
    gl_Position = vec4(0.0);
}
