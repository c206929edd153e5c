!!ARBfp1.0
# four-tap percentage-closer shadow map with SHADOW2D (ARB_fragment_program_shadow)
OPTION ARB_fragment_program_shadow;
PARAM texel = program.local[0];         # (1/width, 1/height, 0, 0)
TEMP base, w, c0, c1, c2, c3, s0, s1, s2, s3;
TEX base, fragment.texcoord[0], texture[0], 2D;
MUL w, texel, fragment.texcoord[1].w;   # offsets scaled by q for TXP
ADD c0, fragment.texcoord[1], w.xzzz;
SUB c1, fragment.texcoord[1], w.xzzz;
ADD c2, fragment.texcoord[1], w.zyzz;
SUB c3, fragment.texcoord[1], w.zyzz;
TXP s0, c0, texture[1], SHADOW2D;
TXP s1, c1, texture[1], SHADOW2D;
TXP s2, c2, texture[1], SHADOW2D;
TXP s3, c3, texture[1], SHADOW2D;
ADD s0, s0, s1;
ADD s2, s2, s3;
ADD s0, s0, s2;
MUL s0, s0, 0.25;
MAD s0, s0.x, 0.75, 0.25;               # keep a quarter of ambient in shadow
MUL result.color, base, s0;
END
