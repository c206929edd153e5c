// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: "As with all arrays, indices used to subscript gl_TexCoord must either be an integral constant expressions, or this array must be re-declared by the shader with a size."
uniform int unit;
void main()
{
    gl_FragColor = gl_TexCoord[unit];
}
