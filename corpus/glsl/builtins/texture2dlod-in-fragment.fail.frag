// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "The built-ins suffixed with "Lod" are allowed only in a vertex shader."
#version 110
uniform sampler2D s;
void main()
{
    gl_FragColor = texture2DLod(s, gl_TexCoord[0].xy, 0.0);
}
