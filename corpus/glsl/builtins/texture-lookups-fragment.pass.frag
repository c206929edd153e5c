// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.7: texture1D, texture1DProj, texture2D, texture2DProj (vec3 and vec4), texture3D, texture3DProj, textureCube, shadow1D, shadow2D, shadow1DProj, shadow2DProj; "the bias parameter is optional for fragment shaders"
#version 110
uniform sampler1D s1;
uniform sampler2D s2;
uniform sampler3D s3;
uniform samplerCube sc;
uniform sampler1DShadow sh1;
uniform sampler2DShadow sh2;
uniform vec4 c;
void main()
{
    vec4 r = texture1D(s1, c.x) + texture1D(s1, c.x, 1.0)
           + texture1DProj(s1, c.xy) + texture1DProj(s1, c, 0.5)
           + texture2D(s2, c.xy) + texture2D(s2, c.xy, -1.0)
           + texture2DProj(s2, c.xyz) + texture2DProj(s2, c) + texture2DProj(s2, c, 2.0)
           + texture3D(s3, c.xyz) + texture3D(s3, c.xyz, 0.0) + texture3DProj(s3, c, 1.0)
           + textureCube(sc, c.xyz) + textureCube(sc, c.xyz, 0.5)
           + shadow1D(sh1, c.xyz) + shadow2D(sh2, c.xyz, 1.0)
           + shadow1DProj(sh1, c) + shadow2DProj(sh2, c, 0.5);
    gl_FragColor = r;
}
