// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// 1.10 4.1 lists mat2, mat3 and mat4 only; mat2x3 is not a 1.10 type
#version 110
uniform mat2x3 m;
void main()
{
    gl_Position = vec4(1.0);
}
