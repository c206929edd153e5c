!!ARBfp1.0
# DP4 and DP4_SAT: four-component dot product (ARBfp 3.11.5.6)
# Per-fragment texture matrix: transform texcoord 0 by the rows of texture matrix 0.
PARAM texMat[] = { state.matrix.texture[0] };
TEMP tc;
DP4 tc.x, texMat[0], fragment.texcoord[0];
DP4 tc.y, texMat[1], fragment.texcoord[0];
DP4 tc.z, texMat[2], fragment.texcoord[0];
DP4_SAT tc.w, texMat[3], fragment.texcoord[0];
TXP result.color, tc, texture[0], 2D;
END
