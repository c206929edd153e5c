!!ARBfp1.0
# fragment.texcoord[3]: beyond the minimum of 2 texture coordinate sets (ARBfp 3.11.3.1, MAX_TEXTURE_COORDS_ARB)
# no warning by default (Mesa takes it); --limits spec-min rejects it
TEMP base;
TEX base, fragment.texcoord[3], texture[0], 2D;
MUL result.color, base, fragment.color;
END
