!!ARBfp1.0
# SLT and SLT_SAT: set on less than (ARBfp 3.11.5.26)
# Mask out texels whose red channel is below the vertex colour red.
TEMP base, m;
TEX base, fragment.texcoord[0], texture[0], 2D;
SLT m, base, fragment.color;
SLT_SAT m.w, base.w, 0.5;
MUL result.color, base, m.r;
END
