// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.1.7 "They can only be declared as function parameters or uniforms"
// 4.3.4 "The attribute qualifier can be used only with the data types float, vec2, vec3, vec4, mat2, mat3, and mat4."
#version 110
attribute sampler2D tex;
void main()
{
    gl_Position = vec4(0.0);
}
