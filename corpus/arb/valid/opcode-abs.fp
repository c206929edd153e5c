!!ARBfp1.0
# ABS and ABS_SAT: component-wise absolute value (ARBfp 3.11.5.1)
# Signed offset map (stored biased in [0,1]) folded into a positive tint.
TEMP offs, tint;
TEX offs, fragment.texcoord[0], texture[0], 2D;
MAD offs, offs, 2.0, -1.0;          # expand to [-1,1]
ABS tint, offs;
ABS_SAT tint.w, -offs.x;
MUL result.color, tint, fragment.color;
END
