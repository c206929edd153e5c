!!ARBfp1.0
# RSQ and RSQ_SAT: scalar reciprocal square root of |x| (ARBfp 3.11.5.22)
# Renormalize an interpolated normal and shade with N.L.
TEMP n, len;
DP3 len.x, fragment.texcoord[0], fragment.texcoord[0];
RSQ len.x, len.x;
RSQ_SAT len.y, -fragment.fogcoord.x;
MUL n, fragment.texcoord[0], len.x;
DP3_SAT n.w, n, fragment.texcoord[1];
MUL result.color, fragment.color, n.w;
END
