!!ARBfp1.0
# decal over a base map by decal alpha, vertex lit, fastest precision hint (ARBfp 3.11.5.14)
OPTION ARB_precision_hint_fastest;
TEMP base, decal;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX decal, fragment.texcoord[1], texture[1], 2D;
LRP base.rgb, decal.a, decal, base;
MUL result.color, base, fragment.color;
END
