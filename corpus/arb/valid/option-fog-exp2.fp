!!ARBfp1.0
# OPTION ARB_fog_exp2 (ARBfp 3.11.4.5.1)
OPTION ARB_fog_exp2;
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL result.color, base, fragment.color;
END
