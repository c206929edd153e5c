!!ARBfp1.0
# parallax mapping: height offsets the coordinates of the colour and normal lookups (ARBfp 3.11.6)
PARAM scaleBias = program.local[0];     # (scale, bias, 0, 0)
PARAM lightDir = program.local[1];
TEMP h, uv, base, N, L;
TEX h, fragment.texcoord[0], texture[1], 2D;      # height in the normal map alpha
MAD h.w, h.w, scaleBias.x, scaleBias.y;
MOV uv, fragment.texcoord[0];
MAD uv.xy, fragment.texcoord[1], h.w, uv;         # texcoord 1: tangent-space eye vector
TEX base, uv, texture[0], 2D;
TEX N, uv, texture[1], 2D;
MAD N, N, 2.0, -1.0;
DP3_SAT L.x, N, lightDir;
MUL result.color, base, L.x;
END
