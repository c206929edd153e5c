// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.7: "Texture lookup functions are available to both vertex and fragment shaders." (without the bias parameter, which "is not accepted in a vertex shader")
uniform sampler1D s1;
uniform sampler2D s2;
uniform sampler3D s3;
uniform samplerCube sc;
uniform sampler1DShadow sh1;
uniform sampler2DShadow sh2;
void main()
{
    vec4 c = gl_MultiTexCoord0;
    vec4 r = texture1D(s1, c.x) + texture1DProj(s1, c.xy) + texture1DProj(s1, c)
           + texture2D(s2, c.xy) + texture2DProj(s2, c.xyz) + texture2DProj(s2, c)
           + texture3D(s3, c.xyz) + texture3DProj(s3, c) + textureCube(sc, c.xyz)
           + shadow1D(sh1, c.xyz) + shadow2D(sh2, c.xyz) + shadow1DProj(sh1, c) + shadow2DProj(sh2, c);
    gl_Position = ftransform() + r;
}
