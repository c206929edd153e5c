!!ARBfp1.0
# MIN and MIN_SAT: component-wise minimum (ARBfp 3.11.5.17)
# Darken blend of two texture layers.
TEMP a, b;
TEX a, fragment.texcoord[0], texture[0], 2D;
TEX b, fragment.texcoord[1], texture[1], 2D;
MIN a, a, b;
MIN_SAT result.color, a, fragment.color;
END
