!!ARBfp1.0
# The texture of unit 0 modulated by the interpolated colour.
TEMP texel;
TEX texel, fragment.texcoord[0], texture[0], 2D;
MUL result.color, texel, fragment.color;
END
