!!ARBfp1.0
# GeForce-era DOT3 bump: light vector packed in the primary colour (ARBfp 3.11.5.5)
TEMP N, L, base;
TEX N, fragment.texcoord[0], texture[0], 2D;
TEX base, fragment.texcoord[1], texture[1], 2D;
MAD N, N, 2.0, -1.0;
MAD L, fragment.color, 2.0, -1.0;
DP3_SAT N, N, L;
MUL result.color.rgb, base, N;
MOV result.color.a, base.a;
END
