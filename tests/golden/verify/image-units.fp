!!ARBfp1.0
# ARGS: --vectors 8
# Texture image units past the eight coordinate sets (Unity samples 8 to 15): both Mesa
# engines bind them.
TEMP a, b;
TEX a, fragment.texcoord[0], texture[8], 2D;
TEX b, fragment.texcoord[1], texture[15], CUBE;
ADD result.color, a, b;
END
