!!ARBfp1.0
# alpha-tested foliage with KIL and linear fog option (ARBfp 3.11.6.4, 3.11.4.5.1)
OPTION ARB_fog_linear;
PARAM alphaRef = { 0.5, 0, 0, 0 };
TEMP base, a;
TEX base, fragment.texcoord[0], texture[0], 2D;
SUB a, base.a, alphaRef.x;
KIL a.x;
MUL result.color, base, fragment.color;
END
