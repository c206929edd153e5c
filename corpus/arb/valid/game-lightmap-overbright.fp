!!ARBfp1.0
# Quake 3-style lightmapped surface with 2x overbright (ARBfp 3.11.5.19, 3.11.5.2)
TEMP base, lm;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX lm, fragment.texcoord[1], texture[1], 2D;
MUL base.rgb, base, lm;
ADD_SAT result.color.rgb, base, base;
MUL result.color.a, base.a, fragment.color.a;
END
