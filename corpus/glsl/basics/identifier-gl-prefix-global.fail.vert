// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 3.7 "Identifiers starting with \"gl_\" are reserved for use by OpenGL, and may not be declared in a shader as either a variable or a function."
#version 110
float gl_scale = 1.0;
void main()
{
    gl_Position = vec4(gl_scale);
}
