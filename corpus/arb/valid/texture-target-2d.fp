!!ARBfp1.0
# TEX with the 2D target on both minimum units (ARBfp 3.11.6)
TEMP base, detail;
TEX base, fragment.texcoord[0], texture[0], 2D;
TEX detail, fragment.texcoord[1], texture[1], 2D;
MUL base, base, detail;
MUL result.color, base, 2.0;
END
