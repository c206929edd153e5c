!!ARBfp1.0
# a fog option and a precision hint together are allowed (ARBfp 3.11.4.5.1, 3.11.4.5.2)
OPTION ARB_precision_hint_fastest;
OPTION ARB_fog_exp2;
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL result.color, base, fragment.color;
END
