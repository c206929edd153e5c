!!ARBfp1.0
# DP3 and DP3_SAT: three-component dot product (ARBfp 3.11.5.5)
# Tangent-space normal map lit by a directional light (direction in local 0).
PARAM lightDir = program.local[0];
TEMP nrm, base, ndotl;
TEX nrm, fragment.texcoord[0], texture[1], 2D;
MAD nrm, nrm, 2.0, -1.0;
DP3_SAT ndotl, nrm, lightDir;
DP3 ndotl.w, nrm, nrm;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL result.color.rgb, base, ndotl;
MOV result.color.a, base.a;
END
