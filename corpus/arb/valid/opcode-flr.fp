!!ARBfp1.0
# FLR and FLR_SAT: component-wise floor (ARBfp 3.11.5.10)
# Posterize a texture to four levels per channel.
TEMP base, q;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL q, base, 4.0;
FLR q, q;
MUL result.color.rgb, q, 0.25;
FLR_SAT result.color.a, base.a;
END
