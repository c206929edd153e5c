// [config]
// expect_result: fail
// glsl_version: 1.10
// [end config]
// Section 8.7 lists texture1D/2D/3D/Cube and shadow1D/2D (with Proj/Lod forms); the overloaded texture() (GLSL 1.30) is not a 1.10 built-in
#version 110
uniform sampler2D s;
void main()
{
    gl_FragColor = texture(s, gl_TexCoord[0].xy);
}
