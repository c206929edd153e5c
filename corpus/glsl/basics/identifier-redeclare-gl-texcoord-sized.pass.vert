// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// 7.6 gl_TexCoord: "indices used to subscript gl_TexCoord must either be an integral constant expressions, or this array must be re-declared by the shader with a size."
// 4.1.9 "It is legal to declare an array without a size and then later re-declare the same name as an array of the same type and specify a size."
#version 110
varying vec4 gl_TexCoord[2];
uniform int unit;
void main()
{
    gl_TexCoord[unit] = vec4(1.0);
    gl_Position = vec4(0.0);
}
