// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7: "The built-ins suffixed with "Lod" are allowed only in a vertex shader."
#version 110
uniform sampler2DShadow s;
void main()
{
    gl_FragColor = shadow2DProjLod(s, gl_TexCoord[0], 0.0);
}
