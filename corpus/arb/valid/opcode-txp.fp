!!ARBfp1.0
# TXP and TXP_SAT: projective texture sample (ARBfp 3.11.6.2)
# Projected spotlight cookie (texcoord 1 from the light's projection) on a base map.
TEMP base, cookie;
TEX base, fragment.texcoord[0], texture[0], 2D;
TXP cookie, fragment.texcoord[1], texture[1], 2D;
TXP_SAT cookie.a, fragment.texcoord[1], texture[1], 2D;
MUL result.color, base, cookie;
END
