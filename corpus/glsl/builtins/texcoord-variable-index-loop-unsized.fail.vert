// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 7.6: "indices used to subscript gl_TexCoord must either be an integral constant expressions, or this array must be re-declared by the shader with a size."
void main()
{
    gl_Position = ftransform();
    for (int i = 0; i < 2; i++)
        gl_TexCoord[i] = gl_MultiTexCoord0;
}
