// [config]
// expect_result: pass
// glsl_version: 1.10
// [end config]
// Section 8.7: "The built-ins suffixed with "Lod" are allowed only in a vertex shader. For the "Lod" functions, lod is directly used as the level of detail."
#version 110
uniform sampler1D s1;
uniform sampler2D s2;
uniform sampler3D s3;
uniform samplerCube sc;
uniform sampler1DShadow sh1;
uniform sampler2DShadow sh2;
void main()
{
    vec4 c = gl_MultiTexCoord0;
    vec4 r = texture1DLod(s1, c.x, 0.0) + texture1DProjLod(s1, c.xy, 1.0) + texture1DProjLod(s1, c, 1.0)
           + texture2DLod(s2, c.xy, 2.0) + texture2DProjLod(s2, c.xyz, 0.0) + texture2DProjLod(s2, c, 0.0)
           + texture3DLod(s3, c.xyz, 0.0) + texture3DProjLod(s3, c, 0.0) + textureCubeLod(sc, c.xyz, 0.0)
           + shadow1DLod(sh1, c.xyz, 0.0) + shadow2DLod(sh2, c.xyz, 0.0)
           + shadow1DProjLod(sh1, c, 0.0) + shadow2DProjLod(sh2, c, 0.0);
    gl_Position = ftransform() + r;
}
