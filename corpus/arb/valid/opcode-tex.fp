!!ARBfp1.0
# TEX and TEX_SAT: texture sample (ARBfp 3.11.6.1)
# Plain textured, colour-modulated surface.
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX_SAT base.a, fragment.texcoord[1], texture[1], 2D;
MUL result.color, base, fragment.color;
END
