!!ARBfp1.0
# MUL and MUL_SAT: component-wise multiply (ARBfp 3.11.5.19)
# Classic modulate: texture times primary colour.
TEMP base;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL base, base, fragment.color.primary;
MUL_SAT result.color, base, 1.5;
END
