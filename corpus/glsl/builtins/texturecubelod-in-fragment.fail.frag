// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "The built-ins suffixed with "Lod" are allowed only in a vertex shader."
uniform samplerCube s;
void main()
{
    gl_FragColor = textureCubeLod(s, gl_TexCoord[0].xyz, 1.0);
}
