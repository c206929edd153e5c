// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 4.2 "A variable declared as an empty array can be re-declared as an array of the same base type."
// 3.7 "Identifiers starting with \"gl_\" are reserved for use by OpenGL, and may not be declared in a shader as either a variable or a function."
#version 110
varying vec3 gl_TexCoord[2];
void main()
{
    gl_Position = vec4(0.0);
}
