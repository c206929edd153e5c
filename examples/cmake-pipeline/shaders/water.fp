!!ARBfp1.0
# Water surface: the texture tinted by the interpolated diffuse term.
PARAM tint = { 0.2, 0.4, 0.9, 1.0 };
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL base, base, tint;
MUL result.color, base, fragment.color;
END
