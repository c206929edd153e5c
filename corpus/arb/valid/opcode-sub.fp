!!ARBfp1.0
# SUB and SUB_SAT: component-wise subtraction (ARBfp 3.11.5.27)
# Difference of two layers, and a colour inversion.
TEMP a, b;
TEX a, fragment.texcoord[0], texture[0], 2D;
TEX b, fragment.texcoord[1], texture[1], 2D;
SUB a, a, b;
SUB_SAT result.color.rgb, 1.0, a;
SUB result.color.a, b.a, 0.0;
END
