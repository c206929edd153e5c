!!ARBfp1.0
# CMP and CMP_SAT: per-component select on sign (ARBfp 3.11.5.3)
# Replace texels whose alpha is below a threshold by the vertex colour.
PARAM threshold = program.local[0];
TEMP base, diff;
TEX base, fragment.texcoord[0], texture[0], 2D;
SUB diff, base.a, threshold.x;
CMP result.color.rgb, diff, fragment.color, base;
CMP_SAT result.color.a, -diff, 0.0, 1.0;
END
